// A snapshot written in pieces by 1, 2 or 3 processes (io/pvtu.hpp; ctest mpi.pvtu.ranks_N):
// 301 points dealt to the ranks in a scattered way (point i to rank i mod P, so no piece is a
// range), each rank writing its piece with the points' indices as the array "particle", rank 0
// the .pvtu index after them. The independent reader (tests/unit/io/check_vtu.py pvtu: the
// index's XML parsed by Python, each piece read by meshio) finds every point once, with the
// closed-form values of its index and the arrays the index declares; an index that leaves a
// piece out is refused, naming the points no piece holds.
// The plans of the runner's pieces (parallel/snapshot_pieces.hpp), made for every rank on one
// process: every cell of the whole snapshot in exactly one piece, written by the owner of its
// first point, on points the piece holds; what a rank sends another is what that one expects.

#include <doctest/doctest.h>

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/io/pvtu.hpp>
#include <rkpm/io/vtk.hpp>
#include <rkpm/parallel/communicator.hpp>
#include <rkpm/parallel/snapshot_pieces.hpp>

#include "mpi/grid_problem.hpp"
#include "support/run_capture.hpp"
#include "support/vtu_formulas.hpp"

namespace test_mpi_pvtu {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

namespace fs = std::filesystem;
using namespace rkpm;

TEST_CASE("a snapshot in pieces: a .vtu per process and the .pvtu index, read back by an independent reader") {
  parallel::communicator world;
  const int P = world.size(), rank = world.rank();
  constexpr int n = 301;
  std::vector<int> mine;
  for (int i = rank; i < n; i += P) mine.push_back(i);
  long id = ::getpid();  // rank 0's: one scratch folder for every rank
  MPI_Bcast(&id, 1, MPI_LONG, 0, world.get());
  const fs::path dir = fs::temp_directory_path() / ("rkpm_mpi_pvtu_" + std::to_string(id));
  const fs::path index = dir / "snapshot_000003.pvtu";
  const test::vtu_snapshot s = test::snapshot_of(mine, true);
  io::write_vtu(io::pvtu_piece(index, rank), s.points, s.data);
  CHECK(io::pvtu_piece(index, rank).filename() == "snapshot_000003_" + std::to_string(rank) + ".vtu");
  MPI_Barrier(world.get());
  if (rank == 0) {
    std::vector<fs::path> pieces;
    for (int r = 0; r < P; ++r) pieces.push_back(io::pvtu_piece(index, r));
    io::write_pvtu(index, pieces, s.data);
    const fs::path script = fs::path(__FILE__).parent_path().parent_path() / "unit" / "io" / "check_vtu.py";
    const auto check = [&](const fs::path& file, int pieces_expected) {
      return test::run_capture("/usr/bin/python3 '" + script.string() + "' pvtu '" + file.string() + "' " +
                               std::to_string(n) + " " + std::to_string(pieces_expected));
    };
    const auto [rc, out] = check(index, P);
    INFO(out);
    REQUIRE_MESSAGE(rc != 2, "meshio is not installed for /usr/bin/python3: apt-get install python3-meshio");
    CHECK(rc == 0);
    if (P > 1) {  // an index without the last piece: its points are in no piece
      pieces.pop_back();
      const fs::path partial = dir / "partial.pvtu";
      io::write_pvtu(partial, pieces, s.data);
      const auto [rc2, out2] = check(partial, P - 1);
      INFO(out2);
      CHECK(rc2 == 1);
      CHECK(out2.find("points held by no piece") != std::string::npos);
    }
    CHECK_THROWS_WITH_AS(io::write_pvtu(dir / "none.pvtu", {}, s.data), doctest::Contains("no pieces"), error);
    fs::remove_all(dir);
  }
  MPI_Barrier(world.get());
}

namespace {
// The cells of a piece on global particle ids, as (type, ids) items.
using cell_item = std::pair<int, std::vector<std::int64_t>>;
std::vector<cell_item> cell_items(const io::vtu_cells& c, const parallel::halo_plan* plan) {
  std::vector<cell_item> out;
  for (std::size_t k = 0, begin = 0; k < c.size(); begin = static_cast<std::size_t>(c.offsets[k++])) {
    cell_item item{c.types[k], {}};
    for (auto e = begin; e < static_cast<std::size_t>(c.offsets[k]); ++e)
      item.second.push_back(plan ? plan->global_particle(static_cast<index_t>(c.connectivity[e])) : c.connectivity[e]);
    out.push_back(std::move(item));
  }
  return out;
}

void check_pieces(const io::vtu_cells& whole, const parallel::particle_partition& p, const std::string& name) {
  INFO(name);
  std::vector<parallel::snapshot_piece> pieces;
  for (int r = 0; r < p.parts; ++r) pieces.push_back(parallel::snapshot_piece_plan(p, whole, r));
  std::vector<cell_item> all;
  for (int r = 0; r < p.parts; ++r) {
    const parallel::halo_plan& h = pieces[r].plan;
    std::vector<stored_index> owned;
    for (index_t I = 0; I < p.particles(); ++I)
      if (p.part[I] == r) owned.push_back(static_cast<stored_index>(I));
    CHECK(h.owned == owned);
    CHECK(std::ranges::is_sorted(h.ghosts));
    std::vector<char> used(h.ghosts.size(), 0);
    for (const std::int64_t i : pieces[r].cells.connectivity) {
      REQUIRE(i >= 0);
      REQUIRE(i < h.local_particles());
      if (i >= static_cast<std::int64_t>(owned.size())) used[i - owned.size()] = 1;
    }
    CHECK(std::ranges::all_of(used, [](char u) { return u == 1; }));  // no ghost beyond the cells' points
    for (const cell_item& c : cell_items(pieces[r].cells, &h)) {
      CHECK(p.part[c.second.front()] == r);
      all.push_back(c);
    }
    // Rank r's list to b names, in order, the particles b expects from r.
    for (const parallel::halo_link& send : h.sends) {
      const auto& receives = pieces[send.rank].plan.receives;
      const auto from = std::ranges::find(receives, r, &parallel::halo_link::rank);
      REQUIRE(from != receives.end());
      std::vector<stored_index> sent, expected;
      for (const stored_index i : send.particles) sent.push_back(h.global_particle(i));
      for (const stored_index i : from->particles) expected.push_back(pieces[send.rank].plan.global_particle(i));
      CHECK(sent == expected);
    }
    for (const parallel::halo_link& receive : h.receives)
      CHECK(std::ranges::any_of(pieces[receive.rank].plan.sends, [&](const auto& s) { return s.rank == r; }));
  }
  std::vector<cell_item> expected = cell_items(whole, nullptr);
  std::ranges::sort(all);
  std::ranges::sort(expected);
  CHECK(all == expected);
}
}  // namespace

TEST_CASE("snapshot pieces: every cell once, on points its piece holds, what is sent what is expected") {
  const test::grid_problem g;
  const io::vtu_cells quads = io::quad_cells(make_grid_mesh(vec2(0.0, 0.0), vec2(g.width, g.height), {12, 8}),
                                             static_cast<std::size_t>(g.size()) + 3);  // 3 lone vertices
  const io::vtu_cells vertices = io::vertex_cells(static_cast<std::size_t>(g.size()));
  std::vector<stored_index> alternate(g.size() + 3);
  for (std::size_t I = 0; I < alternate.size(); ++I) alternate[I] = static_cast<stored_index>(I % 3);
  check_pieces(quads, parallel::given_partition(alternate, 3), "quads, particles dealt by index");
  for (const index_t parts : {1, 2, 3, 4}) {
    const parallel::particle_partition p = parallel::partition_particles(g.table, g.size(), parts);
    check_pieces(vertices, p, fmt::format("vertices, METIS {}", parts));
    std::vector<stored_index> part = p.part;
    part.insert(part.end(), {0, static_cast<stored_index>(parts - 1), 0});
    check_pieces(quads, parallel::given_partition(part, parts), fmt::format("quads, METIS {}", parts));
  }
  CHECK_THROWS_WITH_AS(parallel::snapshot_piece_plan(parallel::given_partition(alternate, 3), quads, 3),
                       doctest::Contains("rank 3 of a partition into 3 parts"), error);
}

}  // namespace test_mpi_pvtu
