// Saved indexes as files: written whole, read through mmap (POSIX; io is outside the
// dependency-free core).

#include "contain/io/index_io.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <utility>
#include <vector>

namespace contain::io {

namespace {

Error io_error(const std::string& path, const std::string& what) {
  return {ErrorKind::io, what + ": " + std::strerror(errno), path};
}

template <class T>
Result<T> named(Result<T> result, const std::string& path) {
  if (result) return result;
  Error error = result.error();
  error.source = path;
  return error;
}

// The pieces one after the other, by writev from where they lie. An existing file is written
// over in place and then cut to the new length (not truncated first): its page-cache pages are
// reused instead of dropped and allocated again, and a file system that flushes a file rewritten
// after truncation (ext4's auto_da_alloc) has no reason to. Either way a write that stops half
// way leaves a file that the header's length and checksums refuse.
Status write_pieces(std::span<const std::span<const std::byte>> pieces, const std::string& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) return io_error(path, "cannot create");
  std::vector<iovec> pending;
  pending.reserve(pieces.size());
  off_t length = 0;
  for (const std::span<const std::byte> piece : pieces) {
    if (piece.empty()) continue;
    pending.push_back({const_cast<std::byte*>(piece.data()), piece.size()});
    length += static_cast<off_t>(piece.size());
  }
  std::size_t next = 0;  // the first piece not yet written whole
  while (next < pending.size()) {
    const auto count = static_cast<int>(std::min<std::size_t>(pending.size() - next, IOV_MAX));
    const ssize_t written = ::writev(fd, &pending[next], count);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      const Error error = io_error(path, "cannot write");
      ::close(fd);
      return error;
    }
    auto left = static_cast<std::size_t>(written);
    while (next < pending.size() && left >= pending[next].iov_len)
      left -= pending[next++].iov_len;
    if (left > 0) {  // part of a piece: the rest of it next
      pending[next].iov_base = static_cast<char*>(pending[next].iov_base) + left;
      pending[next].iov_len -= left;
    }
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || (S_ISREG(st.st_mode) && ::ftruncate(fd, length) != 0)) {
    const Error error = io_error(path, "cannot write");
    ::close(fd);
    return error;
  }
  if (::close(fd) != 0) return io_error(path, "cannot write");
  return Ok{};
}

}  // namespace

MappedFile::MappedFile(MappedFile&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    MappedFile gone(std::move(*this));
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

MappedFile::~MappedFile() {
  if (data_ != nullptr) ::munmap(const_cast<std::byte*>(data_), size_);
}

Result<MappedFile> map_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return io_error(path, "cannot open");
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const Error error = io_error(path, "cannot read");
    ::close(fd);
    return error;
  }
  MappedFile file;
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    return Error{ErrorKind::io, "not a regular file (an index is mapped into memory)", path};
  }
  if (st.st_size > 0) {
    void* p = ::mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ,
                     MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (p == MAP_FAILED) {
      const Error error = io_error(path, "cannot map");
      ::close(fd);
      return error;
    }
    file.data_ = static_cast<const std::byte*>(p);
    file.size_ = static_cast<std::size_t>(st.st_size);
  }
  ::close(fd);
  return file;
}

Status write_index(std::span<const std::byte> bytes, const std::string& path) {
  const std::span<const std::byte> whole[] = {bytes};
  return write_pieces(whole, path);
}

Status write_index(const inside::IndexImage& image, const std::string& path) {
  return write_pieces(image.pieces(), path);
}

Result<IndexFile> read_index_file(const std::string& path) {
  auto file = map_file(path);
  if (!file) return file.error();
  auto header = named(inside::parse_index_header(file->bytes()), path);
  if (!header) return header.error();
  return IndexFile{std::move(*file), *header};
}

// Maps `path`, checks its header and reads the index with `read(file, path)`.
template <class Read>
auto read_whole(const std::string& path, Read read) -> decltype(read(IndexFile{}, path)) {
  auto file = read_index_file(path);
  if (!file) return file.error();
  return read(*file, path);
}

Result<inside::MeshIndex> read_mesh_index(const IndexFile& file, const std::string& path) {
  return named(inside::parse_mesh_index(file.header), path);
}

Result<inside::PolygonIndex> read_polygon_index(const IndexFile& file, const std::string& path) {
  return named(inside::parse_polygon_index(file.header), path);
}

Result<inside::SavedRegionLayer> read_region_layer_index(const IndexFile& file,
                                                         const std::string& path) {
  return named(inside::parse_region_layer(file.header), path);
}

Result<inside::MeshIndex> read_mesh_index(const std::string& path) {
  return read_whole(path,
                    [](const IndexFile& f, const std::string& p) { return read_mesh_index(f, p); });
}

Result<inside::PolygonIndex> read_polygon_index(const std::string& path) {
  return read_whole(
      path, [](const IndexFile& f, const std::string& p) { return read_polygon_index(f, p); });
}

Result<inside::SavedRegionLayer> read_region_layer_index(const std::string& path) {
  return read_whole(
      path, [](const IndexFile& f, const std::string& p) { return read_region_layer_index(f, p); });
}

}  // namespace contain::io
