#include "progress_line.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>

namespace volmesh::cli {

namespace {

constexpr int kBarWidth = 24;
constexpr std::size_t kDefaultColumns = 80;  // when the terminal does not say

std::size_t terminal_columns() {
  winsize w{};
  return ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 0 ? w.ws_col : kDefaultColumns;
}

}  // namespace

ProgressLine::ProgressLine(std::string label, bool quiet)
    : label_(std::move(label)), shown_(!quiet && isatty(STDERR_FILENO) != 0) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::operator()(const std::string& stage, double fraction) {
  if (!shown_) return;
  // A stage repeated by a loop may report a smaller fraction again: the bar never goes back.
  if (std::isfinite(fraction)) done_ = std::max(done_, std::clamp(fraction, 0.0, 1.0));
  const double f = done_;
  const int filled = static_cast<int>(f * kBarWidth);
  const int percent = static_cast<int>(f * 100.0);
  const std::string bar = " [" + std::string(filled, '#') + std::string(kBarWidth - filled, ' ') +
                          "] " +
                          (percent < 10    ? "  "
                           : percent < 100 ? " "
                                           : "") +
                          std::to_string(percent) + "%";
  // The line must not wrap, or the next redraw would start on the wrapped part.
  std::string text = label_ + ": " + stage;
  const std::size_t room = terminal_columns() - 1;
  text.resize(std::min(text.size(), room > bar.size() ? room - bar.size() : 0));
  text += bar;
  if (text == drawn_) return;
  std::cerr << "\r" << text << "\033[K" << std::flush;
  drawn_ = std::move(text);
}

Progress ProgressLine::progress() {
  return [this](const std::string& stage, double fraction) { (*this)(stage, fraction); };
}

void ProgressLine::clear() {
  if (drawn_.empty()) return;
  std::cerr << "\r\033[K" << std::flush;
  drawn_.clear();
}

void add_quiet_flag(CLI::App& app, bool& quiet) {
  app.add_flag("-q,--quiet", quiet,
               "no progress bar on stderr (one is drawn only when stderr is a terminal)");
}

}  // namespace volmesh::cli
