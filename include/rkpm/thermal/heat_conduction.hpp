#pragma once
// heat_conduction<G>: transient heat conduction in the bodies of a discrete model, the library
// side of issue 44 (docs/method.md section 5.9, (86)-(93)). The temperature is a field of RK
// coefficients, T^h(x) = sum_I N_I(x) T_I; Galerkin on the model's quadrature points and shape
// tables (the force loop's, weights with 2 pi R in axisymmetry), lumped capacities C_I = c_p m_I
// (88), conduction in the current configuration of the total-Lagrangian model (87), explicit
// forward Euler (89) sub-cycled under its own stable step (90), boundary sets (91)-(92) and a
// ledger that balances to round-off (93).
//
// Coupling to the mechanical solver (how the explicit step is meant to call it):
//   heat_conduction<G> heat(solver.model(), {props}, solver.physical_mass(), T0, boundaries);
//   each mechanical step (or every few, with their summed dt):
//     s = 0; add_point_heat(model, beta * plastic power per volume, s);      (W, #particles;
//     add_particle_heat(model, J, frictional heat at slave J, s);             thermal/heat_sources.hpp)
//     heat.advance(dt, F_of_point, s);   // sub-cycles itself when dt > stable_time_step()
//     the material update reads heat.temperature_at_point(q)
//   after a re-reference: heat.rebind(new_model, masses), the coefficients kept with their particles
//   (heat_coupling::after_rebuild); contact heat enters through s (or a heat_flux set).
// F is the deformation gradient at each point (a callable q -> mat3, a std::vector<mat3>, or
// nullptr for the reference configuration), as time_step_controller::start takes it.
// One process (a rank's part of a model is refused).

#include <cmath>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include <rkpm/concepts/geometry.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/solver/constraints.hpp>
#include <rkpm/solver/discrete_model.hpp>
#include <rkpm/thermal/boundary_heat.hpp>
#include <rkpm/thermal/conduction_operator.hpp>
#include <rkpm/thermal/heat_ledger.hpp>
#include <rkpm/thermal/heat_sources.hpp>
#include <rkpm/thermal/thermal_boundary.hpp>
#include <rkpm/thermal/thermal_properties.hpp>
#include <rkpm/thermal/thermal_step_bound.hpp>

namespace rkpm::thermal {

struct heat_options {
  double time_step_fraction = 0.8;  // alpha of (90), in (0, 1]
  int first_iterations = 100;       // power iterations of the first measurement of (90)
  int update_iterations = 20;       // of a warm-started measurement, when the bound (90) drifts
};

template <Geometry G>
class heat_conduction {
 public:
  // `bodies`: the thermal properties of each body of the model (model_bodies; one for a model of
  // one body). `mass`: the lumped masses m_I (38) (#particles), the physical ones: not those of
  // mass scaling (section 5.10), which would scale the heat capacity too. Every coefficient starts
  // at `initial_temperature` (K), so T^h = T0 everywhere (partition of unity).
  heat_conduction(const discrete_model& m, std::vector<thermal_properties> bodies, const std::vector<double>& mass,
                  double initial_temperature, std::vector<thermal_boundary> boundaries = {},
                  heat_options options = {})
      : props_(std::move(bodies)), boundaries_(std::move(boundaries)), options_(options) {
    if (!(options_.time_step_fraction > 0.0 && options_.time_step_fraction <= 1.0))
      fail("heat conduction: the time step fraction {} must lie in (0, 1]", options_.time_step_fraction);
    if (!std::isfinite(initial_temperature))
      fail("heat conduction: the initial temperature {} K is not a number", initial_temperature);
    T_.assign(m.particle_count(), initial_temperature);
    rebind(m, mass);
  }

  // Builds everything derived from the model and the masses again (a model rebuilt by a
  // re-reference, section 5.8, or masses changed by mass scaling) and measures the stable step;
  // keeps the coefficients (a re-reference keeps them with their particles, section 5.11), the
  // time and the ledger.
  void rebind(const discrete_model& m, const std::vector<double>& mass) {
    if (m.is_part()) fail("heat conduction runs on one process: this is one rank's part of a model");
    const index_t n = m.particle_count();
    const auto bodies = static_cast<std::size_t>(std::max<index_t>(1, m.bodies.count()));
    if (props_.size() != bodies)
      fail("heat conduction: {} thermal properties for a model of {} bodies: give one per body", props_.size(), bodies);
    if (static_cast<index_t>(mass.size()) != n || static_cast<index_t>(T_.size()) != n)
      fail("heat conduction: {} masses and {} temperatures for {} particles", mass.size(), T_.size(), n);
    m_ = &m;
    mass_ = mass;
    R_.assign(n, 0.0);
    rhs_.assign(n, 0.0);
    D_.assign(m.point_count(), mat2::Zero());
    tile_max_.assign(m.traversal.tiles(), 0.0);
    tile_bad_.assign(m.traversal.tiles(), -1);
    update_capacities();
    for (const thermal_boundary& b : boundaries_) b.validate(n);
    update_boundary_geometry(m.particles.position);
    fixed_ = fixed_temperatures(boundaries_, m.at_particles, capacity_);
    const bool warm = bound_.warm(n);
    bound_.forget();  // the points may be others: nothing to compare with until measured
    evaluate_conduction(nullptr);
    measure_stable_step(warm ? options_.update_iterations : options_.first_iterations);
  }

  // Advances the temperature by dt (s) with sub-steps of equal length, n = ceil(dt / step) with
  // the stable step of (90) at the start, (89). F: the deformation gradient at each point during
  // the step (held over its sub-steps). heat_rate: W per particle, already in coefficient space
  // (#particles, or empty), held over the step. Returns the number of sub-steps.
  template <class PointF = std::nullptr_t>
  index_t advance(double dt, const PointF& F = nullptr, std::span<const double> heat_rate = {}) {
    if (!(dt >= 0.0 && std::isfinite(dt))) fail("heat conduction: the step {} s must be finite and not negative", dt);
    if (!heat_rate.empty() && heat_rate.size() != T_.size())
      fail("heat conduction: {} heat rates for {} particles", heat_rate.size(), T_.size());
    if (dt == 0.0) return 0;
    update_capacities();
    evaluate_conduction(F);
    if (scale() > 1.25 || scale() < 0.8) measure_stable_step(options_.update_iterations);
    const double step = stable_time_step();
    const auto n = static_cast<index_t>(std::max(1.0, std::ceil(dt / step * (1.0 - 1e-12))));
    const double h = dt / static_cast<double>(n);
    for (index_t k = 0; k < n; ++k) {
      if (k > 0) {
        update_capacities();
        evaluate_conduction(F);
      }
      sub_step(h, heat_rate);
    }
    return n;
  }

  // The fixed temperatures imposed now (92), e.g. on the initial field; its heat is booked.
  void impose_fixed_temperatures() { book_fixed(fixed_.impose(T_, boundaries_, capacity_, time_)); }

  // The largest sub-step advance() takes now: alpha 2 / lambda_max(C^-1 K), (90).
  double stable_time_step() const {
    const double lambda = bound_.lambda() * scale();
    return lambda > 0.0 ? options_.time_step_fraction * 2.0 / lambda : std::numeric_limits<double>::infinity();
  }
  // Measures lambda_max(C^-1 K) again at the last evaluated configuration (power iteration, (90)).
  void measure_stable_step(int iterations) {
    const discrete_model& m = *m_;
    bound_.measure(capacity_, D_, area_, iterations, rhs_, [&](const std::vector<double>& x, std::vector<double>& y) {
      conduction_traversal(m, x, y, [&](index_t, index_t q, double, const vec2& grad) -> vec2 {
        return m.points.weight[q] * (D_[q] * grad);
      });
      add_convection_operator(m.at_particles, boundaries_, area_, x, y);
    });
    conductance_scale_ = capacity_scale_ = 1.0;
  }

  double time() const { return time_; }
  void set_time(double t) { time_ = t; }
  const heat_ledger& ledger() const { return ledger_; }
  void set_ledger(const heat_ledger& l) { ledger_ = l; }
  // sum_I C_I T_I (J): with capacities independent of T, the ledger's `stored` is its change.
  double stored_heat() const {
    double sum = 0.0;
    for (std::size_t I = 0; I < T_.size(); ++I) sum += capacity_[I] * T_[I];
    return sum;
  }
  const std::vector<double>& capacities() const { return capacity_; }

  // The coefficients T_I (K; not the temperatures at the particles) and their replacement.
  const std::vector<double>& coefficients() const { return T_; }
  void set_coefficients(std::vector<double> T) {
    if (T.size() != T_.size()) fail("heat conduction: {} coefficients for {} particles", T.size(), T_.size());
    T_ = std::move(T);
    update_capacities();
  }
  // T_I = f(X_I) at the reference positions: exact T^h = f for every linear f (reproduction).
  void set_temperature_field(const std::function<double(const vec2&)>& f) {
    for (index_t I = 0; I < m_->particle_count(); ++I) T_[I] = f(m_->particles.position[I]);
    update_capacities();
  }
  // T^h(x_I) and T^h(X_q), K.
  double temperature_at_particle(index_t I) const { return m_->at_particles.interpolate(I, T_); }
  std::vector<double> particle_temperatures() const {
    std::vector<double> out(T_.size());
    for (index_t I = 0; I < static_cast<index_t>(T_.size()); ++I) out[I] = temperature_at_particle(I);
    return out;
  }
  double temperature_at_point(index_t q) const { return m_->at_points.interpolate(q, T_); }
  // T^h(X_q) at every point (#points), for the material update.
  void point_temperatures(std::vector<double>& out) const {
    out.resize(m_->point_count());
    exec::parallel_for(m_->point_count(), [&](index_t q) { out[q] = temperature_at_point(q); });
  }

  const std::vector<thermal_boundary>& boundaries() const { return boundaries_; }
  // The model, found again at its address (a solver that holds it was moved): the same model.
  void use_model(const discrete_model& m) { m_ = &m; }
  // The areas A_J = L_J omega(x_J) from positions x (#particles, current or reference): sets made
  // on chains measure their lengths again, and in axisymmetry every set takes r_J from x.
  void update_boundary_geometry(std::span<const vec2> x) { boundary_areas_at<G>(boundaries_, x, area_); }

  // Checkpoint (io/checkpoint.hpp): coefficients, time, ledger, the stable step's measurement and
  // vector, and the boundary areas.
  void save(io::checkpoint_writer& w) const { sections(w, *this); }
  void load(io::checkpoint_reader& r) {
    sections(r, *this);
    update_capacities();
  }

 private:
  template <class Archive, class Self>
  static void sections(Archive& a, Self& s) {
    a.array("heat.T", s.T_);
    a.value("heat.time", s.time_);
    a.value("heat.ledger", s.ledger_);
    for (std::size_t k = 0; k < s.area_.size(); ++k) a.array(fmt::format("heat.area_{}", k), s.area_[k]);
    thermal_step_bound::sections(a, s.bound_, s.area_.size());
  }

  // C_I = c_p(T^h(x_I)) m_I, (88), and the capacity part of the bound (90).
  void update_capacities() {
    capacity_.resize(T_.size());
    for (index_t I = 0; I < static_cast<index_t>(T_.size()); ++I) {
      const auto b = static_cast<std::size_t>(m_->bodies.of_particle(I));
      capacity_[I] = props_.c_p(b, props_.capacity_depends_on_T(b) ? temperature_at_particle(I) : 0.0) * mass_[I];
    }
    capacity_scale_ = bound_.capacity_ratio(capacity_);
  }

  // R = K(T) T with the conductances of configuration F (87), and their growth since the last
  // measurement (90).
  // A k(T) is evaluated here, point by point on one thread (a function of the user's, such as a
  // parsed expression, need not be thread-safe), before the parallel traversal.
  template <class PointF>
  void evaluate_conduction(const PointF& F) {
    if (props_.conductivity_depends_on_T()) {
      point_k_.resize(m_->point_count());
      for (index_t q = 0; q < m_->point_count(); ++q)
        point_k_[q] = props_.k(static_cast<std::size_t>(m_->bodies.of_point(q)), temperature_at_point(q));
    }
    conductance_scale_ = conduction_residual(
        *m_, T_, R_, D_, tile_max_, tile_bad_, [&](index_t q, double) { return conductance(F, q); },
        [&](index_t q, const mat2& D) { return bound_.conductance_ratio(q, D); });
  }

  template <class PointF>
  mat2 conductance(const PointF& F, index_t q) const {
    const double k = props_.conductivity_depends_on_T() ? point_k_[q] : props_.k(m_->bodies.of_point(q), 0.0);
    if constexpr (std::is_same_v<PointF, std::nullptr_t>)
      return k * mat2::Identity();
    else if constexpr (std::is_invocable_r_v<mat3, const PointF&, index_t>)
      return k * current_conductance(F(q));
    else
      return k * current_conductance(F[q]);
  }

  // How far the bound of (90) has moved since the measurement: conductances, convection areas
  // and capacities, each in its worst place.
  double scale() const {
    return std::max(conductance_scale_, bound_.area_ratio(boundaries_, area_)) * capacity_scale_;
  }

  // One forward Euler step (89) of length h from the conduction residual R_ of T_ at time_.
  void sub_step(double h, std::span<const double> heat_rate) {
    const index_t n = m_->particle_count();
    for (index_t I = 0; I < n; ++I) rhs_[I] = -R_[I];
    const auto [flux, convection] = add_boundary_heat(m_->at_particles, boundaries_, area_, T_, time_, rhs_);
    double source = 0.0, stored = 0.0;
    for (index_t I = 0; I < n; ++I) {
      double r = rhs_[I];
      if (!heat_rate.empty()) {
        r += heat_rate[I];
        source += heat_rate[I];
      }
      const double T_new = T_[I] + h * r / capacity_[I];
      stored += capacity_[I] * (T_new - T_[I]);
      T_[I] = T_new;
    }
    ledger_.flux += h * flux;
    ledger_.convection += h * convection;
    ledger_.sources += h * source;
    ledger_.stored += stored;
    time_ += h;
    book_fixed(fixed_.impose(T_, boundaries_, capacity_, time_));
  }

  void book_fixed(double heat) {
    ledger_.fixed += heat;
    ledger_.stored += heat;
  }

  const discrete_model* m_ = nullptr;
  body_properties props_;
  std::vector<thermal_boundary> boundaries_;
  heat_options options_;
  std::vector<double> mass_, capacity_, T_, R_, rhs_;
  boundary_areas area_;  // A_J per set
  std::vector<mat2> D_;  // each point's conductance, last evaluated
  thermal_step_bound bound_;
  std::vector<double> point_k_;  // k(T^h(X_q)) when a body's k depends on T
  std::vector<double> tile_max_;
  std::vector<index_t> tile_bad_;
  double conductance_scale_ = 1.0, capacity_scale_ = 1.0;
  fixed_temperatures fixed_;
  double time_ = 0.0;
  heat_ledger ledger_;
};

}  // namespace rkpm::thermal
