// viscoroll: one scene solved over many speeds, a list of scenes (loads, speeds, any field), or
// one scene over speeds with each of several solvers (a material at several temperatures), on
// every core.
//
// The speeds are cut into chunks of fixed length (SweepOptions::chunk) in the order given. Within
// a chunk the speeds are solved in order and each solve is seeded with the previous converged,
// iterated solution of the same chunk where that is a root (continuation, as the command line
// does; a least-squares minimum seeds nothing); the first speed of a chunk starts cold. The
// chunks share nothing, so they run on any number of threads, and the results, returned in the
// order of the speeds, are the same bit for bit whatever the thread count: the thread count
// decides only who solves a chunk, never how.
//
// A sweep can be stopped from another thread (SweepOptions::stop): each thread checks the flag
// before each solve, and the sweep throws SweepStopped once they have all stopped. A solve under
// way is finished first, so a sweep stops within one solve's time. The flag is only read, so a
// sweep that is not stopped gives the same results bit for bit.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <concepts>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>
#include <viscoroll/core/validate.hpp>

namespace viscoroll {

/// Runtime settings of sweep().
struct SweepOptions {
  /// Worker threads; 0 means std::thread::hardware_concurrency() (1 where that is unknown).
  /// Never more threads than chunks are started.
  unsigned threads = 0;
  /// Speeds per chunk of continuation. Smaller chunks spread better over threads; longer ones
  /// continue further. The line solver runs its continuation stages from a seed as from the cold
  /// start, so a seed saves it little time (docs/performance.md, "Where a sweep's time goes").
  std::size_t chunk = 16;
  /// Called after each solve with (solves completed, total), from the worker threads, one call at
  /// a time (under a lock). May be empty.
  std::function<void(std::size_t, std::size_t)> progress;
  /// A stop flag, or null. Once it reads true, every thread stops before its next solve and the
  /// sweep throws SweepStopped after they have all stopped (an exception of a solve already made
  /// is thrown instead, as without the flag). Set it from any thread (Python's Ctrl-C watcher,
  /// a user interface); the sweep never writes it.
  const std::atomic<bool>* stop = nullptr;

  /// Throws std::invalid_argument naming the setting unless 1 <= chunk <= 2^20 and
  /// threads <= 4096.
  void validate() const {
    detail::require(chunk >= 1 && chunk <= (std::size_t(1) << 20), "chunk", chunk,
                    "1 <= chunk <= 1048576");
    detail::require(threads <= 4096u, "threads", threads, "0 <= threads <= 4096 (0: all cores)");
  }

  /// The number of threads a sweep of `chunks` chunks runs on.
  unsigned effective_threads(std::size_t chunks) const {
    unsigned n = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    return static_cast<unsigned>(std::min<std::size_t>(n, std::max<std::size_t>(chunks, 1)));
  }
};

/// Thrown by a sweep stopped by SweepOptions::stop before it solved every item.
class SweepStopped : public std::runtime_error {
 public:
  SweepStopped() : std::runtime_error("viscoroll: the sweep was stopped (SweepOptions::stop)") {}
};

namespace detail {

/// A solver whose solve(scene, seed) takes a solution of a nearby scene as its starting point
/// (LineSolver, BemSolver); others (PlaneSolver) are solved with solve(scene) alone.
template <class Solver, class Scene>
concept SeededSolver = requires(const Solver& solver, const Scene& scene,
                                const typename Solver::Solution* seed) {
  { solver.solve(scene, seed) } -> std::convertible_to<typename Solver::Solution>;
};

}  // namespace detail

/// The sweeps' seed rule: a solution seeds the next speed when it converged, came from an
/// iteration (a closed form, iterations == 0, carries no more than the solver's own cold start)
/// and, where the solution says so, is a root: a least-squares minimum seeds nothing, since the
/// line solver answers a seeded scene without a root from its cold start anyway
/// (LineSolver::solve). For a loop of one's own that continues as sweep() does.
template <class Solution>
bool usable_as_seed(const Solution& s) {
  bool usable = s.converged;
  if constexpr (requires { s.iterations; }) usable = usable && s.iterations > 0;
  if constexpr (requires { s.root; }) usable = usable && s.root;
  return usable;
}

/// A solution with the wall-clock seconds its solve took and what TimedSolver's `Attach` made of
/// it (nothing by default).
template <class Inner, class Extra = std::monostate>
struct Timed {
  Inner solution;      ///< the solver's solution
  double seconds = 0;  ///< the solve's wall-clock time (std::chrono::steady_clock)
  Extra extra{};       ///< what TimedSolver's Attach made of it
};

/// A timed solution seeds as the solution it holds.
template <class Inner, class Extra>
bool usable_as_seed(const Timed<Inner, Extra>& t) {
  return usable_as_seed(t.solution);
}

/// TimedSolver's default Attach: nothing.
struct NoAttachment {
  /// Nothing, for any solution, speed and seconds.
  template <class Inner>
  std::monostate operator()(const Inner&, double, double) const {
    return {};
  }
};

/// `solver` with every solve timed, for sweep(): its Solution is a Timed holding the solver's
/// solution, the seconds and attach(solution, speed, seconds), made on the sweep's worker thread
/// (the Python bindings build their records there). The solver is handed the solution a timed
/// seed holds, and usable_as_seed reads it: a timed sweep gives the plain sweep's numbers bit for
/// bit (the command line and the Python bindings sweep through it).
template <class Solver, class Attach = NoAttachment>
struct TimedSolver {
  /// The solver's solution.
  using Inner = typename Solver::Solution;
  /// What attach makes of a solution.
  using Extra = std::invoke_result_t<const Attach&, const Inner&, double, double>;
  /// A timed solution.
  using Solution = Timed<Inner, Extra>;

  const Solver& solver;  ///< the solver timed
  Attach attach{};       ///< (solution, speed, seconds) -> Extra

  /// Solves `scene` from `seed`'s solution (a solver without seeds: from the scene alone), timed.
  template <class Scene>
  Solution solve(const Scene& scene, const Solution* seed) const {
    const auto start = std::chrono::steady_clock::now();
    Inner inner = [&] {
      if constexpr (detail::SeededSolver<Solver, Scene>)
        return solver.solve(scene, seed != nullptr ? &seed->solution : nullptr);
      else
        return solver.solve(scene);
    }();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Solution out{std::move(inner), seconds, Extra{}};
    out.extra = attach(out.solution, double(scene.speed), seconds);
    return out;
  }
};

namespace detail {

/// The sweeps' engine: items 0 .. n-1 in rows of `row_length` (the last row may be shorter; a row
/// never continues into the next), each row cut into chunks of options.chunk, the chunks spread
/// over threads. solve(i, seed) solves item i from `seed` (nullptr: cold) and returns its
/// solution; a usable solution seeds the next item of its chunk. Returns the solutions in item
/// order; rethrows the first exception in item order after every thread has stopped, else throws
/// SweepStopped if options.stop stopped it short.
template <class Solution, class Solve>
std::vector<Solution> run_chunks(std::size_t n, std::size_t row_length, const SweepOptions& options,
                                 const Solve& solve) {
  options.validate();
  row_length = std::max<std::size_t>(row_length, 1);
  const std::size_t rows = (n + row_length - 1) / row_length;
  const std::size_t per_row = (row_length + options.chunk - 1) / options.chunk;
  const std::size_t chunks = rows * per_row;
  std::vector<std::optional<Solution>> results(n);
  std::vector<std::exception_ptr> errors(chunks);
  std::atomic<std::size_t> next_chunk{0};
  std::atomic<bool> stopped{false};
  std::mutex progress_lock;
  std::size_t completed = 0;

  auto solve_chunk = [&](std::size_t c) {
    const std::size_t row = c / per_row, first = row * row_length + (c % per_row) * options.chunk;
    const std::size_t last = std::min({n, (row + 1) * row_length, first + options.chunk});
    const Solution* seed = nullptr;
    for (std::size_t i = first; i < last; ++i) {
      if (options.stop && options.stop->load(std::memory_order_relaxed)) {
        stopped = true;
        return;
      }
      results[i].emplace(solve(i, seed));
      seed = usable_as_seed(*results[i]) ? &*results[i] : nullptr;
      if (options.progress) {
        const std::lock_guard<std::mutex> lock(progress_lock);
        options.progress(++completed, n);
      }
    }
  };
  auto worker = [&] {
    for (std::size_t c = next_chunk++; c < chunks; c = next_chunk++) {
      try {
        solve_chunk(c);
      } catch (...) {
        errors[c] = std::current_exception();
      }
    }
  };

  const unsigned threads = options.effective_threads(chunks);
  if (threads <= 1) {
    worker();
  } else {
    std::vector<std::jthread> pool;
    pool.reserve(threads);
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
  }  // the jthreads join here
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  if (stopped) throw SweepStopped();

  std::vector<Solution> out;
  out.reserve(n);
  for (auto& r : results) out.push_back(std::move(*r));
  return out;
}

/// solver.solve(scene, seed) where the solver takes a seed, else solver.solve(scene).
template <class Solver, class Scene>
typename Solver::Solution solve_seeded(const Solver& solver, const Scene& scene,
                                       const typename Solver::Solution* seed) {
  if constexpr (SeededSolver<Solver, Scene>)
    return solver.solve(scene, seed);
  else
    return solver.solve(scene);
}

}  // namespace detail

/// Solves `scene` at each of `speeds` (scene.speed is replaced), in chunks of continuation spread
/// over threads (see the file comment). Returns the solutions in the order of `speeds`. An
/// exception thrown by a solve (invalid input) is rethrown here, the first in speed order, after
/// every thread has stopped; SweepStopped if options.stop stopped it. `solver.solve` must be safe
/// to call concurrently (every viscoroll solver is: solve() is const and keeps its work space
/// local).
template <class Solver, class Scene>
std::vector<typename Solver::Solution> sweep(
    const Solver& solver, Scene scene,
    std::type_identity_t<std::span<const decltype(Scene::speed)>> speeds,
    const SweepOptions& options = {}) {
  using Solution = typename Solver::Solution;
  return detail::run_chunks<Solution>(speeds.size(), speeds.size(), options,
                                      [&](std::size_t i, const Solution* seed) {
                                        Scene at = scene;
                                        at.speed = speeds[i];
                                        return detail::solve_seeded(solver, at, seed);
                                      });
}

/// Solves each of `scenes` (any of their fields may vary from one to the next: loads, speeds,
/// curvatures, a roller profile's scene), in chunks of continuation as sweep() over speeds: within
/// a chunk each scene is seeded with the previous one's converged, iterated root, so
/// consecutive scenes should be neighbours. Returns the solutions in the order of `scenes`, the
/// same bit for bit for any thread count; exceptions as sweep() over speeds.
template <class Solver, class Scene>
std::vector<typename Solver::Solution> sweep_scenes(const Solver& solver,
                                                    const std::vector<Scene>& scenes,
                                                    const SweepOptions& options = {}) {
  using Solution = typename Solver::Solution;
  return detail::run_chunks<Solution>(scenes.size(), scenes.size(), options,
                                      [&](std::size_t i, const Solution* seed) {
                                        return detail::solve_seeded(solver, scenes[i], seed);
                                      });
}

/// Solves `scene` with each of `solvers` (one material each: a spectrum at each of several
/// temperatures, at_temperature() in material/temperature_shift.hpp, or any other family) at each
/// of `speeds`. Returns solvers.size() x speeds.size() solutions, row k (solver k) after row
/// k - 1, each row the speed sweep of its solver: cut into chunks of continuation that never
/// cross into another row, all rows' chunks spread over the threads together. The same bit for
/// bit for any thread count, and row k equals sweep(solvers[k], scene, speeds, options); empty
/// `speeds` give no solutions. Exceptions as sweep() over speeds, the first in the order of the
/// result.
template <class Solver, class Scene>
std::vector<typename Solver::Solution> sweep_solvers(
    const std::vector<Solver>& solvers, Scene scene,
    std::type_identity_t<std::span<const decltype(Scene::speed)>> speeds,
    const SweepOptions& options = {}) {
  using Solution = typename Solver::Solution;
  const std::size_t m = speeds.size();  // m = 0: no items, no i % m
  return detail::run_chunks<Solution>(solvers.size() * m, m, options,
                                      [&](std::size_t i, const Solution* seed) {
                                        Scene at = scene;
                                        at.speed = speeds[i % m];
                                        return detail::solve_seeded(solvers[i / m], at, seed);
                                      });
}

}  // namespace viscoroll
