// Consumer of the optional component gmsh: <rkpm/io/gmsh_mesh.hpp> through rkpm::gmsh. Built
// (and so linked against libgmsh) by the packaging test; it meshes the unit square at spacing
// 0.25 (a transfinite 4 x 4 grid of cells) and checks the counts and the area.
#include <cmath>
#include <cstdio>

#include <rkpm/io/gmsh_mesh.hpp>

int main() {
  using rkpm::vec2;
  try {
    const auto body = rkpm::io::mesh_polygon({vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 1)}, 0.25, 2.0);
    double volume = 0.0;
    for (double v : body.particles.volume) volume += v;
    std::printf("rkpm consumer mesh: %td particles, %td cells, volume %.15g\n", body.particles.size(),
                body.mesh.cells(), volume);
    return body.particles.size() == 25 && body.mesh.cells() == 16 && std::abs(volume - 1.0) < 1e-12 ? 0 : 1;
  } catch (const rkpm::error& e) {
    std::printf("rkpm consumer mesh: %s\n", e.what());
    return 2;
  }
}
