#pragma once
// Long library calls from Python: run with the GIL released, their Progress reporting to the
// caller's callback and checking for Ctrl-C, each time with the GIL held. A Python exception
// raised there (KeyboardInterrupt, or the callback's own) unwinds the library call as a C++
// exception and is raised again in Python when the call returns.
#include <pybind11/pybind11.h>

#include <memory>
#include <utility>

#include "volmesh/core/progress.hpp"
#include "volmesh/runs/thread_limit.hpp"

namespace volmesh::python {

namespace py = pybind11;

// `callback`: None or callable(stage: str, fraction: float); it must outlive the call (the
// Python frame that passed it holds it). `threads` > 0: at most this many threads.
class LongCall {
 public:
  LongCall(py::handle callback, int threads);
  // The Progress to hand to the library; copies may be made with the GIL released.
  const Progress& progress() const { return progress_; }

  template <class F>
  auto operator()(F&& f) {
    const auto limit = cli::limit_threads(threads_);
    py::gil_scoped_release release;
    return std::forward<F>(f)();
  }

 private:
  Progress progress_;
  int threads_;
};

}  // namespace volmesh::python
