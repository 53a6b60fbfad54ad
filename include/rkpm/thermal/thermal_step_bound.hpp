#pragma once
// thermal_step_bound: the stable step of heat_conduction's forward Euler (docs/method.md section
// 5.9, (90)). lambda_max(C^-1 K) measured by power iteration (as section 5.6 measures the
// mechanical one: a fixed pseudo-random start, later warm starts with it mixed back in), and the
// bound lambda_max <= lambda_m s that follows the configuration between measurements, from what
// the measurement was taken with: each point's conductance D_q^m, each particle's capacity C_I^m
// and each convection particle's area A_J^m.
//   s = max( max_q mu_max(D_q, D_q^m), max_J A_J / A_J^m ) max_I C_I^m / C_I
// K <= s K^m and C >= C^m / c make it a bound for a symmetric K (without VCI); with VCI's test
// gradients K is not symmetric and it is the same estimate.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <rkpm/core/types.hpp>
#include <rkpm/io/checkpoint.hpp>
#include <rkpm/solver/stable_time_step.hpp>
#include <rkpm/thermal/boundary_heat.hpp>
#include <rkpm/thermal/conduction_operator.hpp>

namespace rkpm::thermal {

class thermal_step_bound {
 public:
  // Measures lambda_m by `iterations` power steps x <- C^-1 K x / max|C^-1 K x| with
  // K x = apply(x, y) (y overwritten), from the fixed start or warm; records D, C and the areas.
  template <class Apply>
  void measure(const std::vector<double>& capacity, const std::vector<mat2>& D, const boundary_areas& area,
               int iterations, std::vector<double>& y, Apply&& apply) {
    const std::size_t n = capacity.size();
    const auto start = [](std::size_t I) { return power_iteration_start(I)[0]; };
    if (mode_.size() != n) {
      mode_.resize(n);
      for (std::size_t I = 0; I < n; ++I) mode_[I] = start(I);
    } else {
      double norm = 0.0;
      for (const double v : mode_) norm = std::max(norm, std::abs(v));
      for (std::size_t I = 0; I < n; ++I) mode_[I] = (norm > 0.0 ? mode_[I] / norm : 0.0) + 0.3 * start(I);
    }
    double lambda = 0.0;
    for (int it = 0; it < iterations; ++it) {
      apply(mode_, y);
      double xKx = 0.0, xCx = 0.0, norm = 0.0;
      for (std::size_t I = 0; I < n; ++I) {
        xKx += mode_[I] * y[I];
        xCx += mode_[I] * capacity[I] * mode_[I];
        y[I] /= capacity[I];
        norm = std::max(norm, std::abs(y[I]));
      }
      lambda = xCx > 0.0 ? xKx / xCx : 0.0;
      if (!(norm > 0.0)) break;  // no conduction and no convection: nothing limits the step
      for (std::size_t I = 0; I < n; ++I) mode_[I] = y[I] / norm;
    }
    lambda_ = lambda;
    D_ = D;
    capacity_ = capacity;
    area_ = area;
  }

  bool measured() const { return !D_.empty(); }
  // Whether a measurement on n particles starts warm (from the last vector).
  bool warm(std::size_t n) const { return mode_.size() == n; }
  // Drops what the last measurement was taken with (a model with other points), keeping the vector.
  void forget() {
    D_.clear();
    capacity_.clear();
    area_.clear();
  }
  double lambda() const { return lambda_; }
  // mu_max(D, D_q^m): 1 before the first measurement.
  double conductance_ratio(index_t q, const mat2& D) const { return measured() ? largest_ratio(D, D_[q]) : 1.0; }
  double capacity_ratio(const std::vector<double>& capacity) const {
    if (capacity_.size() != capacity.size()) return 1.0;
    double c = 0.0;
    for (std::size_t I = 0; I < capacity.size(); ++I) c = std::max(c, capacity_[I] / capacity[I]);
    return c;
  }
  double area_ratio(const std::vector<thermal_boundary>& sets, const boundary_areas& area) const {
    double r = 0.0;
    for (std::size_t s = 0; s < sets.size() && s < area_.size(); ++s)
      if (sets[s].kind == boundary_kind::convection)
        for (std::size_t k = 0; k < area[s].size(); ++k)
          if (area[s][k] > 0.0)
            r = std::max(r, area_[s][k] > 0.0 ? area[s][k] / area_[s][k] : std::numeric_limits<double>::infinity());
    return r;
  }

  // Checkpoint sections (io/checkpoint.hpp); `sets`: how many boundary sets.
  template <class Archive, class Self>
  static void sections(Archive& a, Self& s, std::size_t sets) {
    a.array("heat.mode", s.mode_);
    a.value("heat.lambda", s.lambda_);
    a.array("heat.measured_conductance", s.D_);
    a.array("heat.measured_capacity", s.capacity_);
    if constexpr (!std::is_const_v<Self>) s.area_.resize(sets);
    for (std::size_t k = 0; k < sets; ++k) a.array(fmt::format("heat.measured_area_{}", k), s.area_[k]);
  }

 private:
  std::vector<double> mode_;
  double lambda_ = 0.0;
  std::vector<mat2> D_;
  std::vector<double> capacity_;
  boundary_areas area_;
};

}  // namespace rkpm::thermal
