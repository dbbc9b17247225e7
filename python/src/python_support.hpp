// viscoroll's Python module: what the translation units that talk to Python share (module.cpp,
// study.cpp): waiting for C++ work with the GIL released while Ctrl-C stays answered, a record's
// values as Python objects, and the registration of study.cpp's binding. The solvers' translation
// units never include it (bindings.hpp: pybind11 and the solvers never meet in one unit).
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include "bindings.hpp"

namespace viscoroll::python {

/// How often a waiting solve(), sweep() or study run Python's signal handlers: Ctrl-C is answered
/// within this time plus what the work takes to stop.
inline constexpr std::chrono::milliseconds signal_poll{50};

/// work(stop) on a thread of its own, while the calling thread (holding the GIL) waits for it in
/// steps of signal_poll with the GIL released and runs Python's signal handlers between them
/// (PyErr_CheckSignals), then `on_poll` (if any; a study's progress bar). When a handler raises
/// (Ctrl-C: KeyboardInterrupt), or on_poll throws, `stop` is set and the exception is raised:
/// after the work has ended if `join_on_stop` (a sweep, which stops before its next solve), at
/// once otherwise (a solve that cannot be stopped finishes in the background and its result is
/// dropped; `work` must then own everything it uses). The work's own exception is rethrown.
template <class T>
T interruptible(std::function<T(const std::atomic<bool>&)> work, bool join_on_stop,
                const std::function<void()>& on_poll = {}) {
  struct State {
    std::atomic<bool> stop{false};
    std::mutex lock;
    std::condition_variable ended;
    bool done = false;
    std::optional<T> result;
    std::exception_ptr error;
  };
  auto state = std::make_shared<State>();
  std::thread thread([state, work = std::move(work)] {
    try {
      state->result.emplace(work(state->stop));
    } catch (...) {
      state->error = std::current_exception();
    }
    {
      const std::lock_guard<std::mutex> guard(state->lock);
      state->done = true;
    }
    state->ended.notify_all();
  });
  const auto finished = [&](std::chrono::milliseconds step) {
    const pybind11::gil_scoped_release release;
    std::unique_lock<std::mutex> guard(state->lock);
    return state->ended.wait_for(guard, step, [&] { return state->done; });
  };
  const auto stop = [&] {
    state->stop = true;
    if (join_on_stop) {
      const pybind11::gil_scoped_release release;
      thread.join();
    } else {
      thread.detach();
    }
  };
  while (!finished(signal_poll)) {
    if (PyErr_CheckSignals() != 0) {
      stop();
      throw pybind11::error_already_set();
    }
    if (on_poll) {
      try {
        on_poll();
      } catch (...) {
        stop();
        throw;
      }
    }
  }
  thread.join();
  if (state->error) std::rethrow_exception(state->error);
  return std::move(*state->result);
}

/// A record's value as a Python object: float, int, bool, str, or a list of str.
inline pybind11::object to_python(const Value& value) {
  if (const auto* x = std::get_if<double>(&value)) return pybind11::float_(*x);
  if (const auto* n = std::get_if<long long>(&value)) return pybind11::int_(*n);
  if (const auto* b = std::get_if<bool>(&value)) return pybind11::bool_(*b);
  if (const auto* s = std::get_if<std::string>(&value)) return pybind11::str(*s);
  return pybind11::cast(std::get<std::vector<std::string>>(value));
}

/// Adds study.cpp's solve_items() to the module (the solves of viscoroll.study, docs/python.md).
void register_study(pybind11::module_& m);

}  // namespace viscoroll::python
