#pragma once
// The progress=callable hook of pak.pack, pak.flow and pak.animate. The packers call it on
// their own thread, which holds no GIL; it takes the GIL, lets Python handle its signals (so
// that Ctrl-C, KeyboardInterrupt, stops a run) and calls the callable. Either's exception
// stops the run as a time limit would (RunOptions::stopRequest), and is raised once it has.
#include <atomic>
#include <optional>
#include <utility>

#include <pybind11/pybind11.h>

namespace pak::python {

namespace py = pybind11;

class ProgressHook {
 public:
  explicit ProgressHook(py::object callable) : callable_(std::move(callable)) {}

  // `figures()` builds the dict passed to the callable (with the GIL held).
  template <class Figures>
  void operator()(const Figures& figures) {
    py::gil_scoped_acquire gil;
    if (raised_) return;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!callable_.is_none()) callable_(figures());
    } catch (py::error_already_set& e) {
      raised_ = std::move(e);
      stop_ = true;
    }
  }

  // What the run polls to stop early.
  std::atomic<bool>* stopRequest() { return &stop_; }
  // After the run, with the GIL: raises what the callable (or Ctrl-C) raised.
  void rethrow() {
    if (raised_) throw std::move(*raised_);
  }

 private:
  py::object callable_;
  std::atomic<bool> stop_{false};
  std::optional<py::error_already_set> raised_;
};

}  // namespace pak::python
