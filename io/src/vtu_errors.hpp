#pragma once
// Turning VTK's error reports into one-line messages instead of text on stderr. Included
// only by the VTU reader and writer, the translation units that use VTK.
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <string>

namespace volmesh {

// While alive, VTK's messages go here instead of stderr (VTK prints them both through its
// logger and through its output window, from whichever object hits a problem: reader,
// XML parser, decompressor), and the first error is kept as one line. The routing is
// process-wide, so VTU files are read and written from one thread at a time.
class VtkErrors {
 public:
  VtkErrors()
      : previous_window_(vtkOutputWindow::GetInstance()),
        previous_verbosity_(vtkLogger::GetCurrentVerbosityCutoff()) {
    window_->owner = this;
    vtkOutputWindow::SetInstance(window_);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~VtkErrors() {
    // VTK has no getter for the stderr level; the overall cutoff is that level unless a log
    // file or callback was added.
    vtkLogger::SetStderrVerbosity(previous_verbosity_);
    vtkOutputWindow::SetInstance(previous_window_);
  }
  VtkErrors(const VtkErrors&) = delete;
  VtkErrors& operator=(const VtkErrors&) = delete;

  // The first error, without VTK's "ERROR: In file, line" and "ClassName (0x...): "
  // prefixes; empty if there was none.
  const std::string& first() const { return first_; }

 private:
  class Window : public vtkOutputWindow {
   public:
    static Window* New() {
      auto* window = new Window;
      window->InitializeObjectBase();
      return window;
    }
    void DisplayErrorText(const char* text) override {
      if (owner != nullptr && owner->first_.empty() && text != nullptr) owner->keep(text);
    }
    void DisplayText(const char*) override {}  // warnings and debug output are dropped
    VtkErrors* owner = nullptr;
  };

  void keep(std::string text) {
    if (auto line = text.find('\n'); text.starts_with("ERROR: In ") && line != std::string::npos)
      text.erase(0, line + 1);
    if (auto prefix = text.find("): "); prefix != std::string::npos) text.erase(0, prefix + 3);
    if (auto eol = text.find_first_of("\r\n"); eol != std::string::npos) text.erase(eol);
    first_ = text.empty() ? "VTK reported an error" : text;
  }

  vtkSmartPointer<vtkOutputWindow> previous_window_;
  vtkLogger::Verbosity previous_verbosity_;
  vtkNew<Window> window_;
  std::string first_;
};

}  // namespace volmesh
