#include "long_call.hpp"

#include <chrono>
#include <mutex>
#include <string>

namespace volmesh::python {

namespace {

// The callback and Ctrl-C are looked at this often at most (a stage's first report always):
// taking the GIL on every report of a tight loop would cost the call its speed.
constexpr std::chrono::milliseconds kInterval{50};

struct Reporter {
  py::handle callback;
  std::mutex mutex;  // SignedDistance reports from any thread, one call at a time
  std::chrono::steady_clock::time_point last{};
  std::string stage;

  void operator()(const std::string& now, double fraction) {
    const std::lock_guard lock(mutex);
    const auto time = std::chrono::steady_clock::now();
    if (now == stage && time - last < kInterval) return;
    last = time;
    stage = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!callback.is_none()) callback(now, fraction);
  }
};

}  // namespace

LongCall::LongCall(py::handle callback, int threads) : threads_(threads) {
  auto reporter = std::make_shared<Reporter>();
  reporter->callback = callback;
  progress_ = [reporter](const std::string& stage, double fraction) { (*reporter)(stage, fraction); };
}

}  // namespace volmesh::python
