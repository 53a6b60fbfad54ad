// The material update's step context (concepts/material.hpp, docs/method.md section 4.3.1): the
// solver tells every point's material the step's dt and end time, and the temperature its state
// records; and a state's extra scalars (output_fields) reach the snapshot fields
// (io/solver_output.hpp) with no code of the consumer's. A user's law that heats at a fixed rate
// (dT/dt = 1000 K/s, a stand-in for adiabatic heating) records what it is told at each call.

#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <array>
#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

#include <rkpm/io/solver_output.hpp>

#include "support/solver_fixtures.hpp"

namespace test_unit_solver_material_step {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

struct heated_state {
  double equivalent_plastic_strain = 0.0;
  double plastic_work = 0.0;
  double temperature = 300.0;  // K
  double last_dt = -1.0, last_time = -1.0, told_temperature = -1.0;
  static constexpr auto output_fields() {
    return std::array{std::pair{std::string_view("temperature_K"), &heated_state::temperature}};
  }
};

// Hencky elasticity (material::elastic) whose state heats at `heating` K/s.
struct heated_elastic {
  static constexpr std::string_view name = "heated_elastic";
  using state_type = heated_state;
  material::elastic_constants k;
  double heating = 1000.0;  // K/s
  state_type initial_state() const { return {}; }
  mat3 kirchhoff_stress(const mat3& F, state_type& s, const material_step& step) const {
    s.last_dt = step.dt;
    s.last_time = step.time;
    s.told_temperature = step.temperature;
    s.temperature += heating * step.dt;
    material::elastic_state unused;
    return material::elastic(k).kirchhoff_stress(F, unused);
  }
  double density() const { return k.density; }
  double dilatational_wave_speed() const { return k.dilatational_wave_speed(); }
  const material::elastic_constants& constants() const { return k; }
};

using heated_cfg = config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
                          heated_elastic, contact::none>;

}  // namespace

TEST_CASE("every material update is told the step's dt, its end time and the point's temperature") {
  static_assert(updates_with_step<heated_elastic> && !updates_without_step<heated_elastic>);
  static_assert(Material<heated_elastic>);
  auto p = test::grid_problem<heated_cfg>(vec2(0.0, 0.0), vec2(2e-3, 3e-3), Eigen::Vector2i(5, 7));
  p.material = heated_elastic{test::steel_like()};
  p.initial_velocity = [](const vec2& X) { return vec2(2.0 * X[1] / 3e-3, -X[0] / 2e-3); };
  run_options o;
  o.end_time = 1.0;
  auto s = make_solver<heated_cfg>(std::move(p), o);
  // The evaluation at the start: no time has passed.
  for (const heated_state& st : s.point_states()) {
    CHECK(st.last_dt == 0.0);
    CHECK(st.last_time == 0.0);
    CHECK(st.temperature == 300.0);
  }
  double heated = 300.0;
  for (int k = 0; k < 25; ++k) {
    const double t0 = s.time(), before = heated;
    s.step();
    const double dt = s.time() - t0;
    heated += 1000.0 * dt;
    for (const heated_state& st : s.point_states()) {
      CHECK(st.last_dt == doctest::Approx(dt).epsilon(1e-14));
      CHECK(st.last_time == doctest::Approx(s.time()).epsilon(1e-14));
      CHECK(st.told_temperature == doctest::Approx(before).epsilon(1e-14));  // its state's, before the update
      CHECK(st.temperature == doctest::Approx(heated).epsilon(1e-12));
    }
  }
  REQUIRE(heated > 300.0);

  // The state's temperature is a snapshot field: the same value at every particle (a constant
  // is reproduced by the projection to the particles).
  const io::point_data fields = io::snapshot_fields(s);
  const auto& arrays = fields.arrays();
  const auto temperature = std::find_if(arrays.begin(), arrays.end(), [](const auto& a) { return a.name == "temperature_K"; });
  REQUIRE(temperature != arrays.end());
  CHECK(temperature->values.size() == static_cast<std::size_t>(s.model().particle_count()));
  for (double T : temperature->values) CHECK(T == doctest::Approx(heated).epsilon(1e-10));

  // Deferred (the runner's snapshots): nothing computed until asked, then the same arrays; the
  // stress, projected straight into rows, equals the row-major flattening of the projected tensors.
  const io::point_data deferred = io::snapshot_fields(s, io::field_arrays::deferred);
  REQUIRE(deferred.arrays().size() == arrays.size());
  for (std::size_t k = 0; k < arrays.size(); ++k) {
    CAPTURE(arrays[k].name);
    CHECK(deferred.arrays()[k].name == arrays[k].name);
    CHECK(deferred.arrays()[k].components == arrays[k].components);
    CHECK(deferred.arrays()[k].values.empty());
    CHECK(deferred.arrays()[k].produce() == arrays[k].values);
  }
  const auto stress = std::find_if(arrays.begin(), arrays.end(), [](const auto& a) { return a.name == "stress"; });
  REQUIRE(stress != arrays.end());
  // Byte for byte (the signs of the zeros too): the stress is projected from its in-plane
  // entries and zz only, its out-of-plane shears are the projection of zeros.
  const auto same_bytes = [](const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
  };
  CHECK(same_bytes(stress->values, io::point_data::flat(s.project_to_particles<mat3>(
                                       [&](index_t q) { return s.point_cauchy_stress(q); }))));
  // A material that gives an out-of-plane shear gets the whole projection.
  struct with_shear {
    const decltype(s)& solver;
    const discrete_model& model() const { return solver.model(); }
    mat3 point_cauchy_stress(index_t q) const {
      mat3 sigma = solver.point_cauchy_stress(q);
      sigma(0, 2) = sigma(2, 0) = 1e6 * static_cast<double>(q + 1);
      return sigma;
    }
  } sheared{s};
  std::vector<double> rows(9 * static_cast<std::size_t>(s.model().particle_count()));
  io::detail::stress_rows(sheared)(0, rows.size(), rows.data());
  CHECK(rows[2] != 0.0);
  CHECK(same_bytes(rows, io::point_data::flat(project_to_particles<mat3>(
                             s.model(), [&](index_t q) { return sheared.point_cauchy_stress(q); }))));
  // The vectors, made particle by particle, are those of the whole-array functions.
  const auto displacement = std::find_if(arrays.begin(), arrays.end(), [](const auto& a) { return a.name == "displacement"; });
  REQUIRE(displacement != arrays.end());
  CHECK(same_bytes(displacement->values, io::point_data::flat(s.particle_displacements())));
  std::vector<double> xyz(3 * static_cast<std::size_t>(s.model().particle_count()));
  io::snapshot_points(s)()(0, xyz.size(), xyz.data());
  CHECK(same_bytes(xyz, io::point_data::flat(s.particle_positions())));
}

TEST_CASE("a law that needs nothing of the step keeps its two-argument form") {
  static_assert(updates_without_step<material::elastic>);
  static_assert(updates_with_step<material::j2_plasticity<material::hardening::linear>>);
  // j2 without a step is j2 at dt = 0 and no temperature, bit for bit.
  const material::j2_plasticity<material::hardening::power_law> j2({70e9, 0.3, 2700.0}, {576.79e6, 0.01658, 0.3593});
  auto a = j2.initial_state(), b = j2.initial_state();
  mat3 F = mat3::Identity();
  for (int k = 1; k <= 20; ++k) {
    F(0, 0) = 1.0 + 0.004 * k;
    F(0, 1) = 0.003 * k;
    const mat3 ta = j2.kirchhoff_stress(F, a);
    const mat3 tb = material_update(j2, F, b, material_step{1e-7, 1e-7 * k, std::nan("")});
    CHECK(ta == tb);
  }
  CHECK(a.equivalent_plastic_strain > 0.0);
  CHECK(a.equivalent_plastic_strain == b.equivalent_plastic_strain);
}

}  // namespace test_unit_solver_material_step
