#pragma once
// The execution layer: the loops and reductions of the time step, in one place, so that the
// step says what it computes and this header says how it runs (docs/method.md section 9.7).
// Today the backend is OpenMP on one process (a build without OpenMP runs every loop serially,
// the same results):
//   parallel_for(range, body)            body(I) for every I of the range, statically scheduled
//   parallel_for_each_row<Scratch>(n, body)
//                                        body(I, scratch), dynamically scheduled, a Scratch per
//                                        thread; an rkpm::error is thrown again after the loop
//   for_each_coloured(colour_start, serial_from, body)
//                                        body(k) colour by colour; within a colour in parallel
//   max_over(range, value), min_over     order-free reductions: the same whatever the threads
//   block_sums<K>                        sums in fixed blocks (core/block_sums.hpp)
//   exchange(point, ownership, fields)   where values cross processes; nothing on one process
// Several processes plug in through ownership::group (core/process_group.hpp; on MPI
// parallel/mpi_process_group.hpp): exchange() forwards owned values to the processes that hold
// them as ghosts, block_sums made with the group add their terms over the processes in one
// process's order, and max_over and min_over's callers combine their values with the group's
// max and min, so that the totals do not depend on the partition or the message timing
// (include/rkpm/parallel, docs/method.md section 9.8).

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include <rkpm/core/block_sums.hpp>
#include <rkpm/core/error.hpp>
#include <rkpm/core/process_group.hpp>
#include <rkpm/core/single_thread.hpp>
#include <rkpm/core/types.hpp>

namespace rkpm {

// The indices begin .. end-1.
struct index_range {
  index_t begin = 0, end = 0;
  index_t size() const { return end - begin; }
  bool empty() const { return end == begin; }
};

// Which particles and quadrature points this process computes. Owned particles are updated,
// summed and written here; ghosts are copies of other processes' particles that this process's
// points or contact read (and scatter into), numbered after the owned ones. The points are all
// computed here: the plans of parallel/halo.hpp give a process every point of its owned
// particles, so a point whose support straddles processes is computed by each of them (a
// redundant point) and no force is sent back; what such a point scatters into ghosts is
// discarded. On one process everything is owned.
struct ownership {
  index_range particles;        // owned: 0 .. owned-1
  index_range ghost_particles;  // owned .. particle count - 1
  index_range points;           // owned quadrature points: all of the model's
  // The other processes (null on one process): not owned, the run keeps it alive.
  process_group* group = nullptr;

  static ownership single_process(index_t particle_count, index_t point_count) {
    return {{0, particle_count}, {particle_count, particle_count}, {0, point_count}};
  }
  // Throws unless the ranges cover `particle_count` particles and `point_count` points, owned first.
  void validate(index_t particle_count, index_t point_count) const {
    if (particles.begin != 0 || ghost_particles.begin != particles.end || ghost_particles.end != particle_count ||
        points.begin != 0 || points.end != point_count)
      fail("ownership: owned particles {}..{} and ghosts {}..{} must cover the model's {} particles, owned "
           "first, and the owned points {}..{} its {} points (discrete_model::own; one process: "
           "ownership::single_process)",
           particles.begin, particles.end, ghost_particles.begin, ghost_particles.end, particle_count,
           points.begin, points.end, point_count);
  }
};

// The places in a step where an MPI backend exchanges particle values (docs/method.md 9.7):
//   after_predictor  d(n+1), v(n+1/2) of the owned particles to their ghosts (contact reads them)
//   after_contact    the same after the contact and constraint corrections (the force loop
//                    gathers them)
//   after_scatter    the ghosts' parts of f_int(n+1) added into their owners': nothing with
//                    redundant points (parallel/halo.hpp), kept for a backend without them
//   before_constraints v(n+1) of the owned particles to their ghosts, before the constraints
//                    project it (every rank projects the whole model's constrained particles)
//   stiffness_product  the power iteration's vector before each product with K (the stable step)
enum class exchange_point { after_predictor, after_contact, after_scatter, before_constraints, stiffness_product };

namespace exec {

template <class Body>
void parallel_for(index_range r, Body&& body) {
  if (single_thread()) {
    for (index_t I = r.begin; I < r.end; ++I) body(I);
    return;
  }
#pragma omp parallel for schedule(static)
  for (index_t I = r.begin; I < r.end; ++I) body(I);
}
template <class Body>
void parallel_for(index_t n, Body&& body) {
  parallel_for(index_range{0, n}, body);
}

// body(I, scratch) for I in 0 .. n-1 in chunks of `chunk`, handed out as threads come free
// (rows of uneven cost). An rkpm::error may not leave a parallel region: the first one caught
// is thrown again after the loop (with several failing rows, which one depends on the timing).
template <class Scratch, class Body>
void parallel_for_each_row(index_t n, index_t chunk, Body&& body) {
  std::string first_error;
#pragma omp parallel if (!single_thread())
  {
    Scratch scratch;
#pragma omp for schedule(dynamic, chunk)
    for (index_t I = 0; I < n; ++I) {
      try {
        body(I, scratch);
      } catch (const error& e) {
#pragma omp critical(rkpm_exec_row_error)
        if (first_error.empty()) first_error = e.what();
      }
    }
  }
  if (!first_error.empty()) throw error(first_error);
}

// body(k) for k in colour_start[0] .. colour_start.back()-1, one colour after the other
// (colour c: colour_start[c] .. colour_start[c+1]-1). Below serial_from a colour's k run in
// parallel, one at a time as threads come free, so they must not write the same memory; from
// serial_from on, in order on one thread. The thread team is entered once for all colours.
template <class Body>
void for_each_coloured(const std::vector<index_t>& colour_start, index_t serial_from, Body&& body) {
  const index_t colours = static_cast<index_t>(colour_start.size()) - 1;
  if (single_thread()) {  // colour by colour, each in order: what one thread does below
    for (index_t k = colour_start[0]; k < colour_start[colours]; ++k) body(k);
    return;
  }
#pragma omp parallel
  for (index_t c = 0; c < colours; ++c) {
    if (c < serial_from) {
#pragma omp for schedule(dynamic, 1)
      for (index_t k = colour_start[c]; k < colour_start[c + 1]; ++k) body(k);
    } else {
#pragma omp single
      for (index_t k = colour_start[c]; k < colour_start[c + 1]; ++k) body(k);
    }
  }
}

// The largest and smallest of init and value(I) over the range: the same in any order. value
// may do other per-index work (it runs once for every I), as block_sums' body may.
template <class Value>
double max_over(index_range r, Value&& value, double init = -std::numeric_limits<double>::infinity()) {
  double m = init;
#pragma omp parallel for schedule(static) reduction(max : m) if (!single_thread())
  for (index_t I = r.begin; I < r.end; ++I) m = std::max(m, static_cast<double>(value(I)));
  return m;
}
template <class Value>
double min_over(index_range r, Value&& value, double init = std::numeric_limits<double>::infinity()) {
  double m = init;
#pragma omp parallel for schedule(static) reduction(min : m) if (!single_thread())
  for (index_t I = r.begin; I < r.end; ++I) m = std::min(m, static_cast<double>(value(I)));
  return m;
}

// The largest of init and value(I) over the owned particles of every process (value runs for
// each owned particle here).
template <class Value>
double max_over_owned(const ownership& own, Value&& value, double init) {
  const double m = max_over(own.particles, value, init);
  return own.group ? own.group->max(m) : m;
}

// Makes `fields` (per-particle vectors) consistent across processes at `point` of the step.
// On one process every particle is owned: nothing to send. Ghosts without a backend that
// fills them would be read stale, so they are refused.
template <class... Fields>
void exchange(exchange_point point, const ownership& own, Fields&... fields) {
  if (own.group) {
    if (point != exchange_point::after_scatter) own.group->forward(fields...);  // redundant points: nothing back
    return;
  }
  if (!own.ghost_particles.empty())
    fail("exchange point {}: {} ghost particles, but this build exchanges nothing between processes",
         static_cast<int>(point), own.ghost_particles.size());
  (static_cast<void>(fields), ...);
}

}  // namespace exec
}  // namespace rkpm
