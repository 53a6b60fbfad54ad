#pragma once
// step_companion<Solver>: a component that advances with the solver, attached to it with
// explicit_solver::attach (thermal::heat_coupling is one): called after every step, saved in the
// solver's checkpoints after the solver's own sections, and reporting named values that the
// runner writes into history.csv and summary.json. The names and their order stay fixed through a
// run (they are the history's columns).

#include <string>
#include <utility>
#include <vector>

#include <rkpm/io/checkpoint.hpp>

namespace rkpm {

template <class Solver>
class step_companion {
 public:
  virtual ~step_companion() = default;
  // After step() has finished a step (the solver is between steps).
  virtual void after_step(Solver& s) = 0;
  virtual void save(io::checkpoint_writer& w) const = 0;
  virtual void load(io::checkpoint_reader& r) = 0;
  virtual std::vector<std::pair<std::string, double>> report(const Solver& s) const = 0;
};

}  // namespace rkpm
