#pragma once
// How a long computation reports how far it is: the name of the stage it is in and a rough
// fraction of the whole run done, in [0, 1] (a stage that a loop repeats may report its
// smaller fraction again; a display keeps the largest). A library takes a Progress and calls
// it from the calling thread unless its documentation says otherwise; what is shown, and
// where, is the caller's business (the command line draws a bar on a terminal).
#include <functional>
#include <string>

namespace volmesh {

using Progress = std::function<void(const std::string& stage, double fraction)>;

// progress(stage, fraction) when progress is set.
inline void report(const Progress& progress, const std::string& stage, double fraction) {
  if (progress) progress(stage, fraction);
}

// The progress of one part of a longer run, the part spanning [begin, end] of the whole:
// each fraction f is reported as begin + f (end - begin), each stage with `prefix` before
// it. Empty when `progress` is.
Progress part_of(const Progress& progress, double begin, double end,
                 const std::string& prefix = {});

}  // namespace volmesh
