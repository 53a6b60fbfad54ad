#pragma once
// crack_face_points: the virtual points of the crack faces (discretization/crack_face_rows.hpp)
// as the all-pairs contact sees them (body_contact.hpp; docs/method.md section 6.11, (114)).
// Point p of the faces is index n + p, after the n particles: its row N_I(P) follows the
// particles' rows N_J(X_I) in a table of its own, its reference position P follows theirs, so
// that the physical state x = X + sum_I N_I d_I, the contact point's row and the spreading of a
// force to the coefficients (surface_scratch.hpp) read a face point as they read a particle. Its
// mass, for the paper's reduced mass, is the lumped masses its row interpolates, sum_I N_I(P) m_I.
// Without faces it holds nothing and hands on the particles' own table and positions, so that a
// run without cuts reads exactly what it read before.

#include <span>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/contact/surface_search.hpp>
#include <rkpm/discretization/crack_face_rows.hpp>
#include <rkpm/discretization/shape_table.hpp>

namespace rkpm::contact {

class crack_face_points {
 public:
  // The faces of `body` (none when `wanted` is false or the model has none).
  void setup(const contact_body& body, bool wanted) {
    particles_ = static_cast<index_t>(body.reference_position.size());
    faces_ = crack_face_rows{};
    rows_ = shape_table<2>{};
    X_.clear();
    mass_.clear();
    if (!wanted || !body.crack_faces || body.crack_faces->empty()) return;
    faces_ = *body.crack_faces;
    faces_.rows = shape_table<2>{};  // the rows live in rows_, after the particles'
    rows_ = *body.at_particles;
    X_.assign(body.reference_position.begin(), body.reference_position.end());
    const shape_table<2>& face_rows = body.crack_faces->rows;
    for (index_t p = 0; p < face_rows.points(); ++p) {
      double m = 0.0;
      for (index_t e = face_rows.offset[p]; e < face_rows.offset[p + 1]; ++e) {
        rows_.neighbor.push_back(face_rows.neighbor[e]);
        rows_.N.push_back(face_rows.N[e]);
        m += face_rows.N[e] * body.mass[face_rows.neighbor[e]];
      }
      rows_.offset.push_back(static_cast<stored_index>(rows_.neighbor.size()));
      X_.push_back(faces_.position[p]);
      mass_.push_back(m);
    }
  }

  bool empty() const { return faces_.empty(); }
  // The faces (positions, segments and bodies; their rows are in rows()).
  const crack_face_rows& faces() const { return faces_; }
  // Particles and face points: the index of face point p is particles() + p.
  index_t particles() const { return particles_; }
  index_t points() const { return particles_ + faces_.points(); }
  const shape_table<2>& rows(const contact_body& body) const { return empty() ? *body.at_particles : rows_; }
  std::span<const vec2> reference(const contact_body& body) const {
    return empty() ? body.reference_position : std::span<const vec2>(X_);
  }
  // m: the particles' lumped masses.
  double mass(std::span<const double> m, index_t i) const { return i < particles_ ? m[i] : mass_[i - particles_]; }

  // How far past its ends, in lambda, the segment from a catches a slave (penetrated_segment): 0
  // for a surface's. The points of a crack's two sides coincide where two faces meet, so a slave
  // there sits exactly at the joint of the faces it meets, where a kink of those faces would
  // otherwise leave it behind both and beyond the ends of each (114).
  double overhang(index_t a) const { return a < particles_ ? 0.0 : face_overhang; }
  static constexpr double face_overhang = 0.1;

  // (114), (108) generalised: whether slave J (a particle or a face point) leaves segment a-b of
  // its own body alone. Among particles, (108) itself; with a face point, whether J's row shares
  // a particle with a's or b's (they move with common coefficients: the faces beside J, or near a
  // crack's tip the two faces whose rows overlap, left to the body's stiffness).
  bool within_reach(const shape_table<2>& rows, index_t J, index_t a, index_t b) const {
    if (J < particles_ && a < particles_ && b < particles_) return within_kernel_reach(rows, J, a, b);
    if (J == a || J == b) return true;
    return share_a_particle(rows, J, a) || share_a_particle(rows, J, b);
  }

 private:
  static bool share_a_particle(const shape_table<2>& rows, index_t J, index_t a) {
    for (index_t e = rows.offset[J]; e < rows.offset[J + 1]; ++e)
      for (index_t f = rows.offset[a]; f < rows.offset[a + 1]; ++f)
        if (rows.neighbor[e] == rows.neighbor[f]) return true;
    return false;
  }

  index_t particles_ = 0;
  crack_face_rows faces_;
  shape_table<2> rows_;  // the particles' rows, then the face points'
  std::vector<vec2> X_;  // the particles' reference positions, then the face points'
  std::vector<double> mass_;  // #face points
};

}  // namespace rkpm::contact
