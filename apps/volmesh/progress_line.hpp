#pragma once
// Progress of a subcommand's long steps on stderr: "label: stage [#####     ]  42%",
// redrawn in place on a terminal and erased when done; nothing when stderr is not a
// terminal (logs stay clean) or with --quiet.
#include <string>

#include "volmesh/core/progress.hpp"

namespace CLI {
class App;
}

namespace volmesh::cli {

class ProgressLine {
 public:
  ProgressLine(std::string label, bool quiet);
  ~ProgressLine();  // erases the line
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // Draws the stage and the largest fraction so far when shown; redraws only when the text
  // changes.
  void operator()(const std::string& stage, double fraction);
  // A Progress drawing here (this line must outlive it).
  Progress progress();
  // Erases the line, e.g. before writing to stdout; the next report draws it again.
  void clear();

 private:
  std::string label_;
  bool shown_;
  double done_ = 0.0;  // the largest fraction reported
  std::string drawn_;  // the text on the terminal, empty when none
};

// --quiet: no progress on stderr.
void add_quiet_flag(CLI::App& app, bool& quiet);

}  // namespace volmesh::cli
