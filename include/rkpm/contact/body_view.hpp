#pragma once
// body_view: what the explicit solver hands to a contact policy once, at set-up, and
// step_result: what a contact policy reports after each step (spec/paper.md section 3,
// design.md section 4 "Contact").
//   reference_position  #particles X_I (reference configuration)
//   mass                #particles lumped m_I (axisymmetric: includes 2 pi r)
//   slave               #slaves particle index J of each slave (the body's boundary particles)
//   slave_table         row j: N_I(X_{slave[j]}) for the neighbors I of slave j

#include <vector>

#include <rkpm/core/types.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm::contact {

struct body_view {
  const std::vector<vec2>* reference_position = nullptr;
  const std::vector<double>* mass = nullptr;
  std::vector<index_t> slave;
  shape_table<2> slave_table;
};

struct step_result {
  double work = 0;             // contact work of the step, sum_I f_I . (v_I before + after) / 2 dt
  double max_penetration = 0;  // largest gap found on the predicted configuration
  index_t active = 0;          // slave particles in contact with at least one tool
};

}  // namespace rkpm::contact
