// viscoroll's Python module: solve_items(), the solves behind viscoroll.study (python/viscoroll/
// _study.py, docs/python.md, "Studies: labelled arrays, all cores, a Dask cluster"). A study's
// grid of scenes is a list of items, (scene, speed) pairs in the grid's C order; they are solved
// by viscoroll::sweep_scenes (include/viscoroll/sweep.hpp), the engine of sweep(): cut into chunks
// of `chunk` consecutive items, each chunk solved in order with continuation, the chunks spread
// over threads, the results the same bit for bit for any thread count. A Dask task calls the same
// function on one chunk (threads = 1, chunk = its length), so a study on a cluster repeats the
// local one's solves exactly.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>
#include <viscoroll/core/validate.hpp>
#include <viscoroll/sweep.hpp>

#include "bindings.hpp"
#include "python_support.hpp"

namespace py = pybind11;

namespace viscoroll::python {
namespace {

/// One item of a study: a scene (owned by the caller's Python object), the setup solve() takes
/// for it, and a speed.
struct StudyItem {
  const SceneSpec* scene = nullptr;
  const SolveSetup* setup = nullptr;
  double speed = 0;
};

/// Equal shift laws: the same law with the same constants.
bool same_shift(const std::optional<ShiftLaw<double>>& a,
                const std::optional<ShiftLaw<double>>& b) {
  if (!a || !b) return !a && !b;
  if (a->index() != b->index()) return false;
  if (const auto* w = std::get_if<WlfShift<double>>(&*a)) {
    const auto& v = std::get<WlfShift<double>>(*b);
    return w->c1() == v.c1() && w->c2() == v.c2() && w->t_ref() == v.t_ref();
  }
  const auto& x = std::get<ArrheniusShift<double>>(*a);
  const auto& y = std::get<ArrheniusShift<double>>(*b);
  return x.activation_energy() == y.activation_energy() && x.t_ref() == y.t_ref();
}

/// The same material at the same temperature: what a solution of one scene must share with the
/// next for the line solver to take it as a seed ("a solution of a nearby scene, same material",
/// LineSolver::solve); compared by value, so that a scene and its pickled copy (a Dask task's)
/// compare alike.
bool same_material(const SceneSpec& a, const SceneSpec& b) {
  const MaterialSpec &m = a.material, &n = b.material;
  if (m.elastic != n.elastic || bool(m.prony) != bool(n.prony)) return false;
  if (!m.prony) return m.mu_d == n.mu_d && m.nu == n.nu && m.f == n.f && m.tau == n.tau;
  const auto &p = m.prony->reference, &q = n.prony->reference;
  if (p.g_inf() != q.g_inf() || p.nu() != q.nu() || p.terms().size() != q.terms().size())
    return false;
  for (std::size_t k = 0; k < p.terms().size(); ++k)
    if (p.terms()[k].g != q.terms()[k].g || p.terms()[k].rho != q.terms()[k].rho) return false;
  const bool same_temperature =
      a.temperature == b.temperature || (std::isnan(a.temperature) && std::isnan(b.temperature));
  return same_shift(m.prony->shift, n.prony->shift) && same_temperature;
}

/// The solver of a study's items for viscoroll::sweep_scenes: solve(item, seed) solves the item as
/// solve(scene, speed=..., start=seed) does (solve_with), the seed being the previous item's
/// solution of its chunk where sweep_scenes hands one over (a converged root of an iteration) and
/// the two items share their material, temperature, method and setting; otherwise cold, as the
/// first item of a chunk. The plane method takes no seed, so its numbers do not depend on the
/// chunks.
struct ItemSolver {
  struct Solution {
    SolvedPtr solved;
    const StudyItem* item = nullptr;
    bool converged = false;
    long long iterations = 0;
    bool root = true;  ///< the line method's root (other methods: true)
    std::vector<std::string> breaches;
  };

  static bool continues(const StudyItem& from, const StudyItem& to) {
    return from.setup->method == to.setup->method && from.setup->fast == to.setup->fast &&
           same_material(*from.scene, *to.scene);
  }

  Solution solve(const StudyItem& item, const Solution* seed) const {
    Solution out;
    out.item = &item;
    const Solved* start = seed && continues(*seed->item, item) ? seed->solved.get() : nullptr;
    out.solved = solve_with(*item.scene, *item.setup, item.speed, start, out.breaches);
    const auto field = [&](const char* key) { return out.solved->find(key); };
    if (const Value* c = field("converged")) out.converged = std::get<bool>(*c);
    if (const Value* n = field("iterations")) out.iterations = std::get<long long>(*n);
    if (const Value* r = field("root")) out.root = std::get<bool>(*r);
    return out;
  }
};

constexpr const char* solve_items_doc = R"doc(
solve_items(items, method=None, grid=None, setting=None, tolerance=None, strict=None,
            threads=None, chunk=16, progress=None, check_only=False) -> (records, breaches)

The solves of viscoroll.study: each item, a (Scene, speed) pair, solved as
solve(scene, speed=speed, ...) with the other arguments, by viscoroll::sweep_scenes: the items cut
into chunks of `chunk` consecutive items, each chunk solved in order (an item continues from the
previous one's solution where both have the same material, temperature, method and setting), the
chunks on `threads` threads (None or 0: every core) with the GIL released; the same numbers bit
for bit for any thread count. `progress`, a callable, is called with the number of items solved
from the calling thread every 50 ms while they run. Ctrl-C stops every thread before its next
solve and raises KeyboardInterrupt.

Returns the records (one dict per item: Result.as_dict(), in the order of the items) and the
breaches of the model's assumptions, worded as solve()'s warnings (a list of str, in the order of
the items; raised as ValueError with strict). Invalid input raises ValueError before any solve;
check_only=True checks the items and returns ([], []) without solving them.
)doc";

}  // namespace

void register_study(py::module_& m) {
  m.def(
      "solve_items",
      [](const py::sequence& items, const std::optional<std::string>& method,
         std::optional<long> grid, const std::optional<std::string>& setting,
         std::optional<double> tolerance, std::optional<bool> strict, std::optional<long> threads,
         long chunk, const std::optional<py::function>& progress, bool check_only) {
        const long t = threads.value_or(0);
        viscoroll::detail::require(t >= 0 && t <= 4096, "threads", t,
                                   "0 <= threads <= 4096 (0 or None: all cores)");
        viscoroll::detail::require(chunk >= 1 && chunk <= (1L << 20), "chunk", chunk,
                                   "1 <= chunk <= 1048576");
        // The items and the setup of each distinct scene, checked before any solve. The scenes
        // stay alive in `owners` while the GIL is released.
        std::vector<py::object> owners;
        std::vector<StudyItem> list;
        std::vector<SolveSetup> setups;
        std::unordered_map<const SceneSpec*, std::size_t> setup_of;
        list.reserve(py::len(items));
        for (const auto item : items) {
          if (!py::isinstance<py::tuple>(item) || py::len(item) != 2)
            throw std::invalid_argument(
                "viscoroll: solve_items() takes (Scene, speed) tuples, got " +
                py::repr(item).cast<std::string>());
          const auto pair = py::reinterpret_borrow<py::tuple>(item);
          const py::object scene = pair[0];
          const auto* spec = &scene.cast<const SceneSpec&>();
          const double speed = pair[1].cast<double>();
          viscoroll::detail::require_non_negative("speed", speed);
          if (setup_of.try_emplace(spec, setups.size()).second) {
            owners.push_back(scene);
            setups.push_back(solve_setup(*spec, method, grid, setting, tolerance, strict));
          }
          list.push_back({spec, nullptr, speed});
        }
        for (auto& item : list) item.setup = &setups[setup_of.at(item.scene)];
        if (check_only) return py::make_tuple(py::list(), py::list());

        viscoroll::SweepOptions options;
        options.threads = static_cast<unsigned>(t);
        options.chunk = static_cast<std::size_t>(chunk);
        std::atomic<std::size_t> completed{0};
        options.progress = [&completed](std::size_t done, std::size_t) {
          completed.store(done, std::memory_order_relaxed);
        };
        std::function<void()> on_poll;
        if (progress) on_poll = [&] { (*progress)(completed.load(std::memory_order_relaxed)); };
        std::vector<ItemSolver::Solution> solutions;
        if (!list.empty())
          solutions = interruptible<std::vector<ItemSolver::Solution>>(
              [&](const std::atomic<bool>& stop) {
                viscoroll::SweepOptions stoppable = options;
                stoppable.stop = &stop;
                return viscoroll::sweep_scenes(ItemSolver{}, list, stoppable);
              },
              true, on_poll);

        py::list records, breaches;
        for (const auto& s : solutions) {
          py::dict record;
          for (const auto& [key, value] : s.solved->record())
            record[py::str(key)] = to_python(value);
          records.append(record);
          for (const auto& b : s.breaches) breaches.append(b);
        }
        return py::make_tuple(records, breaches);
      },
      py::arg("items"), py::arg("method") = py::none(), py::arg("grid") = py::none(),
      py::arg("setting") = py::none(), py::arg("tolerance") = py::none(),
      py::arg("strict") = py::none(), py::arg("threads") = py::none(),
      py::arg("chunk") = static_cast<long>(viscoroll::SweepOptions{}.chunk),
      py::arg("progress") = py::none(), py::arg("check_only") = false, solve_items_doc);
}

}  // namespace viscoroll::python
