#pragma once
// Write-to-temporary-then-rename, so that a failed or interrupted writer never leaves a
// partial file under the requested name.
#include <filesystem>
#include <fstream>
#include <string>

namespace volmesh {

class AtomicOutput {
 public:
  // `target` may be a file or (for OpenFOAM cases) a directory.
  explicit AtomicOutput(std::filesystem::path target);
  ~AtomicOutput();  // removes the temporary unless commit() succeeded
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& temporary() const { return temporary_; }
  // Opens the temporary as a binary stream; throws InputError if it cannot.
  std::ofstream open_stream() const;
  // Replaces the target by the temporary.
  void commit();

 private:
  std::filesystem::path target_, temporary_;
  bool committed_ = false;
};

}  // namespace volmesh
