#pragma once
// step_companion<Solver>: a component that advances with the solver, attached to it with
// explicit_solver::attach (thermal::heat_coupling is one): called after every step, saved in the
// solver's checkpoints after the solver's own sections, and reporting named values that the
// runner writes into history.csv and summary.json. The names and their order stay fixed through a
// run (they are the history's columns). When the solver rebuilds its model (a re-reference,
// docs/method.md section 5.8), after_rebuild lets a companion rebind what it derived from it.

#include <string>
#include <utility>
#include <vector>

#include <rkpm/io/checkpoint.hpp>

namespace rkpm {

// What a rebuild of the model keeps: the same particles and the same quadrature points (the same
// material points; a nodal rule's point q is node q), in the same order, each particle's mass.
struct remap_info {
  // The model was rebuilt by reading a re-referenced checkpoint: the companion's state is read
  // next (load), so only what it derives from the model need be built again.
  bool restart = false;
};

template <class Solver>
class step_companion {
 public:
  virtual ~step_companion() = default;
  // After step() has finished a step (the solver is between steps).
  virtual void after_step(Solver& s) = 0;
  // After the model was rebuilt (explicit_solver::rereference(), or a re-referenced checkpoint
  // read), the solver holding the new model; nothing by default.
  virtual void after_rebuild(Solver&, const remap_info&) {}
  virtual void save(io::checkpoint_writer& w) const = 0;
  virtual void load(io::checkpoint_reader& r) = 0;
  virtual std::vector<std::pair<std::string, double>> report(const Solver& s) const = 0;
};

}  // namespace rkpm
