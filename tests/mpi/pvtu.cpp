// A snapshot written in pieces by 1, 2 or 3 processes (io/pvtu.hpp; ctest mpi.pvtu.ranks_N):
// 301 points dealt to the ranks in a scattered way (point i to rank i mod P, so no piece is a
// range), each rank writing its piece with the points' indices as the array "particle", rank 0
// the .pvtu index after them. The independent reader (tests/unit/io/check_vtu.py pvtu: the
// index's XML parsed by Python, each piece read by meshio) finds every point once, with the
// closed-form values of its index and the arrays the index declares; an index that leaves a
// piece out is refused, naming the points no piece holds.

#include <doctest/doctest.h>

#include <mpi.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <rkpm/io/pvtu.hpp>
#include <rkpm/io/vtk.hpp>
#include <rkpm/parallel/communicator.hpp>

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

}  // namespace test_mpi_pvtu
