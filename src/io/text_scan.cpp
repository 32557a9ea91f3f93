#include "io/text_scan.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <regex>
#include <system_error>
#include <utility>
#include <vector>

#include "io/shortest_double.h"

#if defined(__unix__) || defined(__APPLE__)
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

namespace contain::io::detail {

std::string source_name(const std::filesystem::path& path) {
  return path.string();
}

namespace {

// The forms of a password in a connection string: key=value (quoted or not; to the next white
// space, which in a URI's query also hides the parameters after it), the same in a URI's query
// (to the next '&': the secret itself, for hide_secrets), and a URI's user information
// "scheme://user:secret@".
const std::regex& password_pattern() {
  static const std::regex pattern(R"((password\s*=\s*)('(?:[^'\\]|\\.)*'|\S+))", std::regex::icase);
  return pattern;
}
const std::regex& query_password_pattern() {
  static const std::regex pattern(R"(([?&]password=)([^&\s]+))", std::regex::icase);
  return pattern;
}
const std::regex& uri_password_pattern() {
  static const std::regex pattern(R"((://[^:/@\s]*:)([^@\s]*)@)");
  return pattern;
}

}  // namespace

std::string connection_name(const std::string& source) {
  // A connection string may carry a password: never print it.
  const std::string masked = std::regex_replace(source, password_pattern(), "$1***");
  return std::regex_replace(masked, uri_password_pattern(), "$1***@");
}

std::string hide_secrets(const std::string& message, const std::string& source) {
  std::vector<std::string> secrets;
  for (const std::regex* pattern :
       {&password_pattern(), &query_password_pattern(), &uri_password_pattern()}) {
    for (auto it = std::sregex_iterator(source.begin(), source.end(), *pattern);
         it != std::sregex_iterator(); ++it) {
      std::string secret = (*it)[2].str();
      if (secret.size() >= 2 && secret.front() == '\'' && secret.back() == '\'') {
        secrets.push_back(secret.substr(1, secret.size() - 2));
      }
      secrets.push_back(std::move(secret));
    }
  }
  std::string out = connection_name(message);
  for (const std::string& secret : secrets) {
    // A secret of a few characters would also hide those letters wherever the message has them:
    // its own forms are hidden above already.
    if (secret.size() < 4) continue;
    for (std::size_t at = out.find(secret); at != std::string::npos; at = out.find(secret, at))
      out.replace(at, secret.size(), "***");
  }
  return out;
}

namespace {

// Why `path` cannot be read as a file, the same words for every reader.
Status check_readable(const std::filesystem::path& path, const std::string& source) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) {
    return make_error(ErrorKind::io, "cannot open the file: it does not exist", source);
  }
  if (std::filesystem::is_directory(status)) {
    return make_error(ErrorKind::io, "cannot read the file: it is a directory", source);
  }
  return Ok{};
}

}  // namespace

Result<std::string> read_file(const std::filesystem::path& path) {
  const std::string source = source_name(path);
  if (Status readable = check_readable(path, source); !readable) return readable.error();
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    return make_error(ErrorKind::io, std::string("cannot open the file: ") + std::strerror(errno),
                      source);
  }
  // A regular file is read in one piece into a string of its size: growing the string chunk by
  // chunk copied a 200 MB point file about twice over (5% of a whole run). Whatever a file that
  // changes meanwhile holds past that size is appended as from a stream.
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size == 0) return read_stream(in, source);
  std::string data(static_cast<std::size_t>(size), '\0');
  in.read(data.data(), static_cast<std::streamsize>(size));
  data.resize(static_cast<std::size_t>(in.gcount()));
  if (in.bad()) return make_error(ErrorKind::io, "reading failed", source);
  if (in) {
    auto rest = read_stream(in, source);
    if (!rest) return rest;
    data += *rest;
  }
  return data;
}

Result<BlockInput> BlockInput::open(const std::filesystem::path& path) {
  if (path == "-") return BlockInput(stdin, "<stdin>", 0);
  const std::string source = source_name(path);
  if (Status readable = check_readable(path, source); !readable) return readable.error();
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    return make_error(ErrorKind::io, std::string("cannot open the file: ") + std::strerror(errno),
                      source);
  }
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  return BlockInput(file, source, ec ? 0 : size);
}

BlockInput::BlockInput(BlockInput&& other) noexcept
    : file_(std::exchange(other.file_, nullptr)),
      source_(std::move(other.source_)),
      size_(other.size_) {}

BlockInput::~BlockInput() {
  if (file_ != nullptr && file_ != stdin) std::fclose(file_);
}

Result<std::size_t> BlockInput::read(char* to, std::size_t bytes) {
  const std::size_t got = std::fread(to, 1, bytes, file_);
  if (got < bytes && std::ferror(file_) != 0) {
    return make_error(ErrorKind::io, "reading failed", source_);
  }
  return got;
}

#if defined(__unix__) || defined(__APPLE__)
namespace {
// The window made present ahead of the reader, and the text dropped behind it at a time: large
// enough that the system calls are few (a few for 40 MB), small beside the memory of 10^8 points.
constexpr std::size_t kPresentWindow = std::size_t{8} << 20;
constexpr std::size_t kReleaseWindow = std::size_t{16} << 20;

std::size_t page_bytes() {
  static const auto bytes = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  return bytes;
}
}  // namespace

std::optional<MappedText> MappedText::map(std::FILE* file, std::uintmax_t size) {
  if (file == nullptr || size == 0 || size > std::numeric_limits<std::size_t>::max()) return {};
  const int fd = ::fileno(file);
  struct stat st {};
  if (fd < 0 || ::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) ||
      static_cast<std::uintmax_t>(st.st_size) != size || ::lseek(fd, 0, SEEK_CUR) != 0) {
    return {};
  }
  void* data = ::mmap(nullptr, static_cast<std::size_t>(size), PROT_READ, MAP_PRIVATE, fd, 0);
  if (data == MAP_FAILED) return {};
#if defined(MADV_SEQUENTIAL)
  (void)::madvise(data, static_cast<std::size_t>(size), MADV_SEQUENTIAL);
#endif
  return MappedText(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

MappedText::MappedText(MappedText&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)),
      present_(other.present_),
      released_(other.released_) {}

MappedText::~MappedText() {
  if (data_ != nullptr) ::munmap(const_cast<char*>(data_), size_);
}

bool MappedText::reach(std::size_t to) {
  if (to <= present_) return true;
  const std::size_t from = present_ / page_bytes() * page_bytes();
  present_ = std::min(size_, std::max(to, present_ + kPresentWindow));
#if defined(MADV_POPULATE_READ)
  // Faults a window at once instead of a page (or a fault-around of 16) at a time. Otherwise a
  // hint: on a kernel without it (EINVAL) the pages come by faults as ever.
  if (::madvise(const_cast<char*>(data_) + from, present_ - from, MADV_POPULATE_READ) != 0) {
    return errno != EFAULT && errno != EIO;  // pages past the file's end, or unreadable
  }
#else
  (void)from;
#endif
  return true;
}

void MappedText::release(std::size_t from) {
  const std::size_t upto = std::min(from, size_) / page_bytes() * page_bytes();
  if (upto < released_ + kReleaseWindow) return;
  (void)::madvise(const_cast<char*>(data_) + released_, upto - released_, MADV_DONTNEED);
  released_ = upto;
}
#else
std::optional<MappedText> MappedText::map(std::FILE*, std::uintmax_t) {
  return {};
}
MappedText::MappedText(MappedText&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}
MappedText::~MappedText() = default;
bool MappedText::reach(std::size_t) {
  return true;
}
void MappedText::release(std::size_t) {}
#endif

Result<std::string> read_stream(std::istream& in, const std::string& source) {
  std::string data;
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), buffer.size());
    data.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) return make_error(ErrorKind::io, "reading failed", source);
  return data;
}

Status write_file(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) {
    return make_error(ErrorKind::io,
                      std::string("cannot open the file for writing: ") + std::strerror(errno),
                      source_name(path));
  }
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.flush();
  if (!out) return make_error(ErrorKind::io, "writing failed", source_name(path));
  return Ok{};
}

Error make_error(ErrorKind kind, std::string message, const std::string& source,
                 std::int64_t line) {
  return Error{kind, std::move(message), source, line};
}

NumberStatus parse_double(const char*& p, const char* end, double& out) {
  const char* start = p;
  // from_chars takes no '+'; accept it only before a digit or a point so "+-1" stays an error.
  if (start != end && *start == '+' && start + 1 != end &&
      (std::isdigit(static_cast<unsigned char>(start[1])) || start[1] == '.')) {
    ++start;
  }
  double value = 0.0;
  auto [ptr, ec] = std::from_chars(start, end, value, std::chars_format::general);
  if (ec == std::errc::invalid_argument || ptr == start) return NumberStatus::not_a_number;
  if (ec == std::errc::result_out_of_range) {
    // libstdc++ reports underflow as out of range too; strtod (correctly rounded in glibc, "C"
    // decimal point as this token has no other) gives the subnormal or zero, or HUGE_VAL.
    std::string token(start, ptr);
    errno = 0;
    value = std::strtod(token.c_str(), nullptr);
    p = ptr;
    if (!std::isfinite(value)) return NumberStatus::not_finite;
    out = value;
    return NumberStatus::ok;
  }
  p = ptr;
  if (!std::isfinite(value)) return NumberStatus::not_finite;
  out = value;
  return NumberStatus::ok;
}

bool parse_int64(const char*& p, const char* end, std::int64_t& out) {
  const char* start = p;
  if (start != end && *start == '+' && start + 1 != end &&
      std::isdigit(static_cast<unsigned char>(start[1]))) {
    ++start;
  }
  std::int64_t value = 0;
  auto [ptr, ec] = std::from_chars(start, end, value);
  if (ec != std::errc{} || ptr == start) return false;
  p = ptr;
  out = value;
  return true;
}

char* write_double(char* at, double value) {
  // std::to_chars' bytes, several times faster (issue 26: half the time of slicing to WKT).
  return write_shortest_double(at, value);
}

void append_double(std::string& out, double value) {
  std::array<char, kMaxDoubleChars> buffer{};
  out.append(buffer.data(), write_double(buffer.data(), value));
}

std::string number_id(double value) {
  constexpr double limit = 9223372036854775808.0;  // 2^63: every whole double below fits int64
  if (value == std::floor(value) && std::abs(value) < limit) {
    return std::to_string(static_cast<std::int64_t>(value));
  }
  std::string out;
  append_double(out, value);
  return out;
}

std::string quote_token(const char* p, const char* end) {
  if (p == end) return "the end of the file";
  if (*p == '\n' || *p == '\r') return "the end of the line";
  const char* q = p;
  // A token ends at white space or, past its first character, at punctuation of the formats.
  while (q != end && !is_space(*q) && q - p < 24 &&
         (q == p || (*q != ',' && *q != '(' && *q != ')' && *q != ']' && *q != '}'))) {
    ++q;
  }
  if (q == p) q = p + 1;
  std::string token(p, q);
  for (char& c : token) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  }
  return "'" + token + "'";
}

std::int64_t line_of_offset(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  return 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n');
}

std::string_view skip_bom(std::string_view text) {
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  return text;
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return ext;
}

}  // namespace contain::io::detail
