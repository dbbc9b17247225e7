// viscoroll: one scene solved over many speeds, on every core.
//
// The speeds are cut into chunks of fixed length (SweepOptions::chunk) in the order given. Within
// a chunk the speeds are solved in order and each solve is seeded with the previous converged,
// iterated solution of the same chunk (continuation, as the command line does); the first speed of
// a chunk starts cold. The chunks share nothing, so they run on any number of threads, and the
// results, returned in the order of the speeds, are the same bit for bit whatever the thread
// count: the thread count decides only who solves a chunk, never how.
#pragma once

#include <algorithm>
#include <concepts>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <thread>
#include <type_traits>
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

namespace detail {

/// A solver whose solve(scene, seed) takes a solution of a nearby scene as its starting point
/// (LineSolver, BemSolver); others (PlaneSolver) are solved with solve(scene) alone.
template <class Solver, class Scene>
concept SeededSolver = requires(const Solver& solver, const Scene& scene,
                                const typename Solver::Solution* seed) {
  { solver.solve(scene, seed) } -> std::convertible_to<typename Solver::Solution>;
};

/// A solution seeds the next speed when it converged and came from an iteration: a closed form
/// (iterations == 0) carries no more than the solver's own cold start.
template <class Solution>
bool usable_as_seed(const Solution& s) {
  if constexpr (requires { s.iterations; }) return s.converged && s.iterations > 0;
  return s.converged;
}

}  // namespace detail

/// Solves `scene` at each of `speeds` (scene.speed is replaced), in chunks of continuation spread
/// over threads (see the file comment). Returns the solutions in the order of `speeds`. An
/// exception thrown by a solve (invalid input) is rethrown here, the first in speed order, after
/// every thread has stopped. `solver.solve` must be safe to call concurrently (every viscoroll
/// solver is: solve() is const and keeps its work space local).
template <class Solver, class Scene>
std::vector<typename Solver::Solution> sweep(
    const Solver& solver, Scene scene,
    std::type_identity_t<std::span<const decltype(Scene::speed)>> speeds,
    const SweepOptions& options = {}) {
  using Solution = typename Solver::Solution;
  options.validate();
  const std::size_t n = speeds.size();
  const std::size_t chunks = (n + options.chunk - 1) / options.chunk;
  std::vector<std::optional<Solution>> results(n);
  std::vector<std::exception_ptr> errors(chunks);
  std::atomic<std::size_t> next_chunk{0};
  std::mutex progress_lock;
  std::size_t completed = 0;

  auto solve_chunk = [&](std::size_t c) {
    Scene at = scene;
    const Solution* seed = nullptr;
    for (std::size_t i = c * options.chunk; i < std::min(n, (c + 1) * options.chunk); ++i) {
      at.speed = speeds[i];
      if constexpr (detail::SeededSolver<Solver, Scene>)
        results[i].emplace(solver.solve(at, seed));
      else
        results[i].emplace(solver.solve(at));
      seed = detail::usable_as_seed(*results[i]) ? &*results[i] : nullptr;
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

  std::vector<Solution> out;
  out.reserve(n);
  for (auto& r : results) out.push_back(std::move(*r));
  return out;
}

}  // namespace viscoroll
