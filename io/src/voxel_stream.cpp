#include "voxel_stream.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>

#include "voxel_samples.hpp"

namespace volmesh::voxel {

namespace fs = std::filesystem;

ByteSource::ByteSource(fs::path path, std::uint64_t offset, bool gzip) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  struct stat st {};
  if (fd_ < 0 || ::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    const std::string why = fd_ < 0 ? std::strerror(errno) : "not a regular file";
    if (fd_ >= 0) ::close(fd_);
    fail(path_, "cannot open (" + why + ")");
  }
  const auto size = static_cast<std::uint64_t>(st.st_size);
  remaining_ = size - std::min(offset, size);
  if (::lseek(fd_, static_cast<off_t>(std::min(offset, size)), SEEK_SET) < 0) {
    ::close(fd_);
    fail(path_, "cannot seek to byte " + std::to_string(offset));
  }
  if (gzip) {
    gz_ = ::gzdopen(fd_, "rb");  // takes over the descriptor, starting at the current offset
    if (gz_ == nullptr) {
      ::close(fd_);
      fail(path_, "cannot open the gzip stream");
    }
    fd_ = -1;
    ::gzbuffer(gz_, 1 << 17);
  }
}

ByteSource::~ByteSource() {
  if (gz_ != nullptr) ::gzclose(gz_);
  if (fd_ >= 0) ::close(fd_);
}

std::size_t ByteSource::read(char* out, std::size_t n) {
  std::size_t done = 0;
  while (done < n) {
    const std::size_t chunk = std::min<std::size_t>(n - done, 1u << 30);
    std::ptrdiff_t got;
    if (gz_ != nullptr) {
      got = ::gzread(gz_, out + done, static_cast<unsigned>(chunk));
      if (got < 0) {
        int code = Z_OK;
        std::string why = ::gzerror(gz_, &code);
        if (why.rfind("<fd:", 0) == 0)
          why.erase(0, why.find(": ") + 2);  // zlib's name for the descriptor
        fail(path_, "gzip data: " + why);
      }
    } else {
      got = ::read(fd_, out + done, chunk);
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) fail(path_, std::string("read error (") + std::strerror(errno) + ")");
      remaining_ -= static_cast<std::uint64_t>(got);
    }
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  return done;
}

std::optional<std::uint64_t> ByteSource::raw_remaining() const {
  if (gz_ != nullptr) return std::nullopt;
  return remaining_;
}

std::string read_exact(ByteSource& source, std::uint64_t count, const std::string& what,
                       std::string prefix) {
  const fs::path& path = source.path();
  const auto need = [&] { return std::to_string(count) + " bytes of data (" + what + ")"; };
  if (prefix.size() > count)
    fail(path, "data: " + std::to_string(prefix.size()) + " bytes or more where " + need() +
                   " were expected");
  if (auto left = source.raw_remaining()) {  // raw: the file size tells before anything is read
    const std::uint64_t have = prefix.size() + *left;
    if (have < count)
      fail(path, "data truncated: " + std::to_string(have) + " bytes for " + need());
    if (have > count)
      fail(path, "data: " + std::to_string(have) + " bytes where " + need() + " were expected");
  }
  std::string bytes = std::move(prefix);
  if (source.raw_remaining()) bytes.reserve(count);  // checked against the file size above
  constexpr std::size_t kChunk = std::size_t{16} << 20;  // growth step for gzip data
  while (bytes.size() < count) {
    const std::size_t old = bytes.size();
    bytes.resize(old + std::min<std::uint64_t>(count - old, kChunk));
    const std::size_t got = source.read(bytes.data() + old, bytes.size() - old);
    if (old + got < bytes.size())
      fail(path, "data truncated: " + std::to_string(old + got) + " bytes for " + need());
  }
  char extra;
  if (source.read(&extra, 1) != 0) fail(path, "data: more than " + need());
  return bytes;
}

}  // namespace volmesh::voxel
