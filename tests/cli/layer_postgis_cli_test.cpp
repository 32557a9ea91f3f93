// contain inside --layer PG:... against a real PostgreSQL 15 server with PostGIS, started for the
// test on a Unix socket in a scratch directory and stopped at the end (also when a check
// fails). The layer is loaded with ogr2ogr; the answers must be the bytes the same layer gives
// from a file. PostgreSQL refuses to run as root: under root (CI) the server runs as the
// unprivileged user `nobody`, its scratch directory owned by that user.

#include <gtest/gtest.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "cli/layer_data.h"
#include "cli/run.h"

namespace contain::test {
namespace {

namespace fs = std::filesystem;

const fs::path kPgBin = "/usr/lib/postgresql/15/bin";
const fs::path kPostgisControl = "/usr/share/postgresql/15/extension/postgis.control";

// A PostgreSQL server of its own: initdb, pg_ctl start on a socket in `dir_`, pg_ctl stop in
// the destructor. `error()` says what went wrong when it did not start.
class PostgisServer {
 public:
  PostgisServer() {
    if (!fs::exists(kPgBin / "postgres") || !fs::exists(kPgBin / "initdb")) {
      error_ = "the PostgreSQL 15 server is not installed (" + (kPgBin / "postgres").string() +
               "): install postgresql-15 and postgresql-15-postgis-3 (the README's test line "
               "does)";
      return;
    }
    if (!fs::exists(kPostgisControl)) {
      error_ = "PostGIS for PostgreSQL 15 is not installed (" + kPostgisControl.string() +
               "): install postgresql-15-postgis-3 (the README's test line does)";
      return;
    }
    char pattern[] = "/tmp/contain-postgis-XXXXXX";
    if (mkdtemp(pattern) == nullptr) {
      error_ = "cannot create a scratch directory in /tmp";
      return;
    }
    dir_ = pattern;
    if (geteuid() == 0) {
      const passwd* nobody = getpwnam("nobody");
      if (nobody == nullptr) {
        error_ = "running as root, and there is no user 'nobody' to run the server as";
        return;
      }
      uid_ = static_cast<int>(nobody->pw_uid);
      gid_ = static_cast<int>(nobody->pw_gid);
      if (chown(dir_.c_str(), nobody->pw_uid, nobody->pw_gid) != 0) {
        error_ = "cannot give the scratch directory to 'nobody'";
        return;
      }
    }
    const CliRun init = as_server((kPgBin / "initdb").string(),
                                  {"-D", (dir_ / "data").string(), "-A", "trust", "-U", "postgres",
                                   "-E", "UTF8", "--no-sync", "--no-locale"});
    if (init.exit_code != 0) {
      error_ = "initdb failed: " + init.err + init.out;
      return;
    }
    const CliRun start =
        as_server((kPgBin / "pg_ctl").string(),
                  {"-D", (dir_ / "data").string(), "-l", (dir_ / "server.log").string(), "-w", "-t",
                   "60", "-o", "-k " + dir_.string() + " -c listen_addresses='' -F", "start"});
    started_ = true;  // stop even if pg_ctl only half succeeded
    if (start.exit_code != 0) {
      error_ = "pg_ctl start failed: " + start.err + start.out + log();
      return;
    }
    const CliRun extension = psql("CREATE EXTENSION postgis;");
    if (extension.exit_code != 0) {
      error_ = "CREATE EXTENSION postgis failed: " + extension.err;
      return;
    }
  }

  ~PostgisServer() {
    if (started_) {
      (void)as_server((kPgBin / "pg_ctl").string(),
                      {"-D", (dir_ / "data").string(), "-m", "immediate", "-w", "stop"});
    }
    if (!dir_.empty()) {
      std::error_code ec;
      fs::remove_all(dir_, ec);
    }
  }
  PostgisServer(const PostgisServer&) = delete;
  PostgisServer& operator=(const PostgisServer&) = delete;

  [[nodiscard]] const std::string& error() const { return error_; }
  /// The GDAL connection string of the server's database.
  [[nodiscard]] std::string connection() const {
    return "PG:host=" + dir_.string() + " user=postgres dbname=postgres";
  }
  /// A directory the server's user can read (files handed to ogr2ogr go there).
  [[nodiscard]] const fs::path& dir() const { return dir_; }

  [[nodiscard]] CliRun psql(const std::string& sql) const {
    return run_program("psql", {"-h", dir_.string(), "-U", "postgres", "-d", "postgres", "-v",
                                "ON_ERROR_STOP=1", "-q", "-c", sql});
  }

 private:
  [[nodiscard]] CliRun as_server(const std::string& program,
                                 const std::vector<std::string>& args) const {
    return run_program(program, args, "", uid_, gid_);
  }
  [[nodiscard]] std::string log() const {
    std::ifstream in(dir_ / "server.log");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }

  fs::path dir_;
  std::string error_;
  bool started_ = false;
  int uid_ = -1, gid_ = -1;
};

CliRun ogr2ogr_into(const PostgisServer& server, const std::string& file, const std::string& table,
                    const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args{
      "-f",  "PostgreSQL", server.connection(),  file,   "-nln",
      table, "-lco",       "GEOMETRY_NAME=geom", "-lco", "SPATIAL_INDEX=GIST"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_program("ogr2ogr", args);
}

TEST(InsideLayerPostgisCli, TableLoadedByOgr2ogrGivesTheSameBytesAsTheFile) {
  const PostgisServer server;
  ASSERT_EQ(server.error(), "");
  TempDir dir;
  const std::string geojson = dir.write("layer.geojson", layer_geojson());
  const std::string points = dir.write("p.txt", case_points());
  const CliRun load = ogr2ogr_into(server, geojson, "parcels");
  ASSERT_EQ(load.exit_code, 0) << load.err;
  const CliRun from_file =
      run_contain({"inside", "--layer", geojson, "--id", "name", "--points", points});
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  const CliRun from_table = run_contain({"inside", "--layer", server.connection(), "--layer-name",
                                         "parcels", "--id", "name", "--points", points});
  EXPECT_EQ(from_table.exit_code, 0) << from_table.err;
  EXPECT_EQ(from_table.out, from_file.out);
  // A second table: the layer must then be named, and the error lists the tables.
  const CliRun again = ogr2ogr_into(server, geojson, "parcels_copy");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const CliRun ambiguous =
      run_contain({"inside", "--layer", server.connection(), "--points", points});
  EXPECT_EQ(ambiguous.exit_code, 2);
  EXPECT_NE(ambiguous.err.find("parcels_copy"), std::string::npos) << ambiguous.err;
  const CliRun missing = run_contain(
      {"inside", "--layer", server.connection(), "--layer-name", "roads", "--points", points});
  EXPECT_EQ(missing.exit_code, 2);
}

TEST(InsideLayerPostgisCli, NaturalEarthCountriesFromPostgisEqualTheShapefile) {
  const fs::path countries =
      "/usr/lib/python3/dist-packages/geopandas/datasets/naturalearth_lowres/"
      "naturalearth_lowres.shp";
  ASSERT_TRUE(fs::exists(countries))
      << countries << " is missing: install python3-geopandas (the README's test line does)";
  const PostgisServer server;
  ASSERT_EQ(server.error(), "");
  // PRECISION=NO: the shapefile's numeric widths (pop_est) would overflow numeric(n, m).
  const CliRun load = ogr2ogr_into(server, countries.string(), "countries",
                                   {"-nlt", "PROMOTE_TO_MULTI", "-lco", "PRECISION=NO"});
  ASSERT_EQ(load.exit_code, 0) << load.err;
  // Random points over the world, and a grid of half degrees: borders drawn along meridians
  // and parallels (Africa, North America) put many of its points on shared edges.
  TempDir dir;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> lon(-180, 180), lat(-90, 90);
  std::string text;
  for (int k = 0; k < 20000; ++k)
    text += std::to_string(lon(rng)) + " " + std::to_string(lat(rng)) + "\n";
  for (int x = -360; x <= 360; ++x) {
    for (int y = -180; y <= 180; y += 12)
      text += std::to_string(0.5 * x) + " " + std::to_string(0.5 * y) + "\n";
  }
  const std::string points = dir.write("p.txt", text);
  const CliRun from_file =
      run_contain({"inside", "--layer", countries.string(), "--id", "name", "--points", points});
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  const CliRun from_table = run_contain({"inside", "--layer", server.connection(), "--layer-name",
                                         "countries", "--id", "name", "--points", points});
  EXPECT_EQ(from_table.exit_code, 0) << from_table.err;
  EXPECT_EQ(from_table.out, from_file.out);
  EXPECT_NE(from_file.out.find("Brazil"), std::string::npos);
}

}  // namespace
}  // namespace contain::test
