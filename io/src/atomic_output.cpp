#include "atomic_output.hpp"

#include <unistd.h>

#include <system_error>

#include "volmesh/core/errors.hpp"

namespace volmesh {

namespace fs = std::filesystem;

AtomicOutput::AtomicOutput(fs::path target) : target_(std::move(target).lexically_normal()) {
  // "case.foam/" names the directory itself, not something inside it.
  if (!target_.has_filename()) target_ = target_.parent_path();
  // Same directory as the target, so that the rename cannot cross file systems.
  temporary_ = target_.parent_path() /
               ("." + target_.filename().string() + ".tmp" + std::to_string(::getpid()));
  if (!target_.parent_path().empty() && !fs::is_directory(target_.parent_path()))
    throw InputError(target_.string() + ": output directory " +
                     target_.parent_path().string() + " does not exist");
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(temporary_, ec);
  }
}

std::ofstream AtomicOutput::open_stream() const {
  std::ofstream out(temporary_, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(target_.string() + ": cannot open for writing");
  return out;
}

void AtomicOutput::commit() {
  std::error_code ec;
  if (fs::is_directory(temporary_) && fs::exists(target_)) fs::remove_all(target_, ec);
  fs::rename(temporary_, target_, ec);
  if (ec) throw InputError(target_.string() + ": cannot write (" + ec.message() + ")");
  committed_ = true;
}

}  // namespace volmesh
