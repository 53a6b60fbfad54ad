// Exact restart (solver/checkpoint.hpp, io/checkpoint.hpp, docs/method.md section 9.5): N steps
// uninterrupted and N/2 steps, a checkpoint, a fresh solver from the same problem that reads it
// and N/2 more steps give the same coefficients, velocities, point states, energies, time, step
// count and time step, compared with == (bit for bit, one thread). Two configurations: plane
// strain J2 pressed into the corner of a moving L-shaped tool with penalty contact and Coulomb
// friction (penalty leaves particles inside, so the segment that held a particle at the last
// step decides which face acts: leaving the held segments out of the checkpoint makes this test
// fail) and axisymmetric J2 with a prescribed velocity (axis and velocity constraints); the first
// again re-referenced every 7 steps (docs/method.md section 5.8).
// A checkpoint of another configuration, format version, problem or section layout, a truncated
// file and a file that is not a checkpoint are refused with a message naming the reason; a file
// with one bit flipped anywhere (2002 places: every byte of the prefix, header and section table,
// three in every section, 600 pseudo-random) is refused as damaged, naming the part the bit is
// in by the layout parsed here on its own, and leaves the solver as it was; the write leaves no
// temporary file; the header (with the writer's description) is read without a solver, and the
// latest checkpoint of a folder is found by its name.

#include <doctest/doctest.h>

#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <set>
#include <string>

#include "support/solver_fixtures.hpp"

namespace test_unit_solver_checkpoint {  // compiled with its neighbours in one program (tests/CMakeLists.txt)

using namespace rkpm;

namespace {

using ps_contact_cfg =
    config<kernel::cubic_spline, correction::linear, quadrature::q2, geometry::plane_strain,
           material::j2_plasticity<material::hardening::linear>,
           contact::particle_to_segment<contact::enforcement::penalty, contact::friction::coulomb>>;
using axi_cfg = config<kernel::cubic_spline, correction::linear, quadrature::q4, geometry::axisymmetric,
                       material::j2_plasticity<material::hardening::power_law>, contact::none>;

// A block thrown and pressed (a body force) down and sideways into the corner of an L-shaped
// tool (floor and wall meet at a vertex concave for the tool, where the block's corner is behind
// both faces) that moves up and toward it. Penalty stiffness as in test::check_combination.
problem_for<ps_contact_cfg> striking_block(int nx = 7, double density = 7800.0) {
  auto p = test::grid_problem<ps_contact_cfg>(vec2(-2e-3, 0.0), vec2(2e-3, 3e-3), Eigen::Vector2i(nx, 5),
                                              {200e9, 0.3, density});
  p.contact = test::make_contact<ps_contact_cfg::contact_type>({contact::rigid_tool(
      "corner", {vec2(-5e-3, -1e-5), vec2(2e-3 + 1e-5, -1e-5), vec2(2e-3 + 1e-5, 5e-3)}, contact::side::left,
      contact::tool_motion::constant_velocity(vec2(-5.0, 10.0)))},
      1e9);
  p.initial_velocity = [](const vec2& X) { return vec2(30.0 + 2e3 * X[1] * X[1], -20.0 * (1.0 + 0.2 * std::sin(900.0 * X[1]))); };
  p.body_force = vec2(3e7, -1e8);  // keeps the block pressed into the corner
  return p;
}

// A cylinder compressed by its top face moving down at 10 m/s (reached over 1 microsecond).
problem_for<axi_cfg> compressed_cylinder() {
  const Eigen::Vector2i n(5, 6);
  auto p = test::grid_problem<axi_cfg>(vec2(0.0, 0.0), vec2(2e-3, 3e-3), n);
  test::squeeze_from_top(p, 3e-3, 10.0, 1e-6);
  return p;
}

run_options options() {
  run_options o;
  o.end_time = 1.0;
  o.time_step_update_interval = 3;  // step-size updates on both sides of the checkpoint
  return o;
}

std::filesystem::path scratch_folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / fmt::format("rkpm_checkpoint_{}_{}", name, ::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const rkpm::error& e) {
    return e.what();
  }
  return "(no error)";
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Fields of a checkpoint's bytes (layout: io/checkpoint_format.hpp).
template <class T>
T load(const std::string& bytes, std::size_t at) {
  T v;
  std::memcpy(&v, bytes.data() + at, sizeof(T));
  return v;
}
template <class T>
void store(std::string& bytes, std::size_t at, const T& v) {
  std::memcpy(bytes.data() + at, &v, sizeof(T));
}
// The prefix's and the table's checksums again: a file changed on purpose, as another version or
// build would write it, rather than damaged.
void reseal(std::string& bytes) {
  const auto table = load<std::uint64_t>(bytes, 20);
  store(bytes, bytes.size() - 4, io::crc32_of(bytes.data() + table, bytes.size() - 4 - table));
  store(bytes, 28, io::crc32_of(bytes.data(), 28));
}

// A part of a checkpoint file, [begin, end), and how the reader names it when damaged.
struct file_part {
  std::size_t begin, end;
  std::string name;
};
// The parts of a checkpoint, from its layout as documented, read here without the reader: the
// prefix and the header ("the header"), each section's values and the table with its checksum.
std::vector<file_part> layout_of(const std::string& bytes) {
  const auto table = load<std::uint64_t>(bytes, 20);
  std::size_t at = table;
  auto next = [&]<class T>(T) {
    at += sizeof(T);
    return load<T>(bytes, at - sizeof(T));
  };
  const auto header_bytes = next(std::uint64_t{});
  next(std::uint32_t{});
  const auto sections = next(std::uint64_t{});
  std::vector<file_part> parts{{0, io::checkpoint_prefix_bytes + header_bytes, "the header"}};
  for (std::uint64_t k = 0; k < sections; ++k) {
    const auto length = next(std::uint64_t{});
    const std::string name = bytes.substr(at, length);
    at += length;
    const auto count = next(std::uint64_t{}), size = next(std::uint64_t{});
    next(std::uint32_t{});
    parts.push_back({parts.back().end, parts.back().end + count * size, "section '" + name + "'"});
  }
  CHECK(at + 4 == bytes.size());  // the table's checksum closes the file
  parts.push_back({table, bytes.size(), "the section table"});
  return parts;
}

bool same_state(const material::j2_state& a, const material::j2_state& b) {
  return a.elastic_left_cauchy_green == b.elastic_left_cauchy_green && a.previous_deformation == b.previous_deformation &&
         a.equivalent_plastic_strain == b.equivalent_plastic_strain && a.plastic_work == b.plastic_work;
}

template <class S>
void check_identical(const S& a, const S& b) {
  CHECK(a.steps() == b.steps());
  CHECK(a.time() == b.time());
  CHECK(a.time_step() == b.time_step());
  CHECK(a.min_time_step() == b.min_time_step());
  CHECK(a.max_time_step() == b.max_time_step());
  CHECK(a.coefficients() == b.coefficients());
  CHECK(a.coefficient_velocities() == b.coefficient_velocities());
  CHECK(a.internal_force() == b.internal_force());
  bool det_F = a.model().point_count() == b.model().point_count();
  for (index_t q = 0; det_F && q < a.model().point_count(); ++q) det_F = a.point_det_F(q) == b.point_det_F(q);
  CHECK(det_F);
  bool states = a.point_states().size() == b.point_states().size();
  for (std::size_t q = 0; states && q < a.point_states().size(); ++q)
    states = same_state(a.point_states()[q], b.point_states()[q]);
  CHECK(states);
  const energy_balance &x = a.energy(), &y = b.energy();
  CHECK(x.initial_kinetic == y.initial_kinetic);
  CHECK(x.kinetic == y.kinetic);
  CHECK(x.internal == y.internal);
  CHECK(x.plastic == y.plastic);
  CHECK(x.external == y.external);
  CHECK(x.contact == y.contact);
  CHECK(x.constraint == y.constraint);
  CHECK(x.largest_imbalance == y.largest_imbalance);
  CHECK(a.max_penetration() == b.max_penetration());
  CHECK(a.last_contact().active == b.last_contact().active);
  CHECK(a.contact().reactions() == b.contact().reactions());
  CHECK(a.min_stretch() == b.min_stretch());
  CHECK(x.remap == y.remap);
  CHECK(a.rereferences() == b.rereferences());
  CHECK(a.model().particles.position == b.model().particles.position);
  CHECK(a.model().particles.support == b.model().particles.support);
}

// N steps straight and N/2 + checkpoint + N/2 in a fresh solver; returns the straight run.
template <class Cfg>
solver_for<Cfg> check_restart(const std::function<problem_for<Cfg>()>& make, int N,
                              const run_options& o = options()) {
  test::run_serially();
  const auto dir = scratch_folder("restart");
  auto straight = make_solver<Cfg>(make(), o);
  for (int k = 0; k < N; ++k) straight.step();

  auto first = make_solver<Cfg>(make(), o);
  for (int k = 0; k < N / 2; ++k) first.step();
  const auto path = dir / io::checkpoint_file_name(first.steps());
  write_checkpoint(first, path, Cfg::name());
  CHECK(std::filesystem::exists(path));
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 1);

  auto second = make_solver<Cfg>(make(), o);
  read_checkpoint(second, path, Cfg::name());
  check_identical(first, second);  // the state as read
  for (int k = N / 2; k < N; ++k) second.step();
  check_identical(straight, second);
  std::filesystem::remove_all(dir);
  return straight;
}

}  // namespace

TEST_CASE("checkpoint file names sort in step order; the latest of a folder is found") {
  CHECK(io::checkpoint_file_name(1234) == "checkpoint_0000001234.rkpmcp");
  CHECK(io::checkpoint_file_name(99) < io::checkpoint_file_name(100));
  const auto dir = scratch_folder("latest");
  CHECK(!io::latest_checkpoint(dir));
  for (const std::string name : {io::checkpoint_file_name(99), io::checkpoint_file_name(100),
                                 io::checkpoint_file_name(101) + ".tmp", std::string("summary.json")})
    std::ofstream(dir / name) << "x";
  CHECK(io::latest_checkpoint(dir) == dir / io::checkpoint_file_name(100));
  std::filesystem::remove_all(dir);
}

TEST_CASE("the header (configuration, counts, description) is read without a solver") {
  test::run_serially();
  const auto dir = scratch_folder("header");
  auto s = make_solver<ps_contact_cfg>(striking_block(), options());
  s.step();
  const auto path = dir / io::checkpoint_file_name(s.steps());
  write_checkpoint(s, path, ps_contact_cfg::name(), R"({"case": "striking_block", "friction": 0.2})");
  const io::checkpoint_header h = io::read_checkpoint_header(path);
  CHECK(h.identity.configuration == ps_contact_cfg::name());
  CHECK(h.identity.particles == 35);
  CHECK(h.identity.points == s.model().point_count());
  CHECK(h.identity.slaves == static_cast<index_t>(s.slave_particles().size()));
  CHECK(h.identity.tools == 1);
  CHECK(h.description == R"({"case": "striking_block", "friction": 0.2})");
  std::filesystem::remove_all(dir);
}

TEST_CASE("plane strain J2 with a moving tool and Coulomb friction restarts bit for bit") {
  const auto s = check_restart<ps_contact_cfg>([] { return striking_block(); }, 40);
  // The run exercised what the checkpoint must carry: contact with friction, plasticity.
  CHECK(s.last_contact().active > 0);
  bool sliding = false;
  for (const auto& pair : s.contact().active_pairs()) sliding = sliding || pair.tangential_force.norm() > 0.0;
  CHECK(sliding);
  CHECK(s.energy().plastic > 0.0);
}

TEST_CASE("re-referenced every 7 steps, pressed into a moving tool with friction, restarts bit for bit") {
  // The checkpoint at step 20 follows the re-references at steps 7 and 14: the model is rebuilt
  // from the current reference it holds (leaving the supports out of it makes this test fail),
  // the contact keeps what the last step left across each re-reference.
  run_options o = options();
  o.rereference.every_steps = 7;
  const auto s = check_restart<ps_contact_cfg>([] { return striking_block(); }, 40, o);
  CHECK(s.rereferences() == 5);
  CHECK(s.last_contact().active > 0);
  CHECK(s.energy().plastic > 0.0);
}

TEST_CASE("axisymmetric J2 with prescribed velocities restarts bit for bit") {
  // 1100 steps: the checkpoint at step 550 follows the controller's power iteration at step 500,
  // so the warm-start vector and the estimate's step must be restored (leaving the vector out
  // of the checkpoint makes this test fail).
  const auto s = check_restart<axi_cfg>(compressed_cylinder, 1100);
  CHECK(s.energy().constraint != 0.0);
  CHECK(s.energy().plastic > 0.0);
}

TEST_CASE("a checkpoint that does not fit is refused with the reason") {
  test::run_serially();
  const auto dir = scratch_folder("refused");
  auto s = make_solver<ps_contact_cfg>(striking_block(), options());
  for (int k = 0; k < 3; ++k) s.step();
  const auto path = dir / "good.rkpmcp";
  write_checkpoint(s, path, ps_contact_cfg::name());
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto write = [&](const std::string& name, const std::string& content) {
    std::ofstream(dir / name, std::ios::binary) << content;
    return dir / name;
  };
  auto fresh = make_solver<ps_contact_cfg>(striking_block(), options());
  auto refusal = [&](const std::filesystem::path& p, const std::string& configuration = ps_contact_cfg::name()) {
    return message_of([&] { read_checkpoint(fresh, p, configuration); });
  };

  const std::string other = refusal(path, axi_cfg::name());
  CHECK(other.find("configuration '" + ps_contact_cfg::name() + "'") != std::string::npos);
  CHECK(other.find("'" + axi_cfg::name() + "'") != std::string::npos);

  CHECK(refusal(write("half.rkpmcp", bytes.substr(0, bytes.size() / 2))).find("is truncated") != std::string::npos);
  CHECK(refusal(write("cut.rkpmcp", bytes.substr(0, bytes.size() - 1))).find("is truncated") != std::string::npos);
  CHECK(refusal(write("notes.txt", "t = 1 ms\n")).find("is not an rkpm checkpoint file") != std::string::npos);
  CHECK(refusal(write("prefix.rkpmcp", bytes.substr(0, 20))).find("is truncated") != std::string::npos);
  CHECK(refusal(write("version.rkpmcp", bytes.substr(0, 10))).find("is truncated") != std::string::npos);
  // Another version: a later one (its prefix checks) and one from before the checksums (3).
  for (const std::uint32_t version : {io::checkpoint_format_version + 1, std::uint32_t{3}}) {
    std::string other_version = bytes;
    store(other_version, 8, version);  // the format version follows the 8-byte magic
    reseal(other_version);
    CHECK(refusal(write("version.rkpmcp", other_version))
              .find(fmt::format("format version {}, this build reads version {}", version,
                                io::checkpoint_format_version)) != std::string::npos);
  }
  CHECK(refusal(dir / "missing.rkpmcp").find("does not exist") != std::string::npos);
  std::string renamed = bytes;  // a section another build would write in its place, in the table
  renamed.replace(renamed.find("solver.d", load<std::uint64_t>(bytes, 20)), 8, "solver.q");
  reseal(renamed);
  CHECK(refusal(write("renamed.rkpmcp", renamed)).find("of another build: section 'solver.q' where 'solver.d' was expected") !=
        std::string::npos);

  auto wider = make_solver<ps_contact_cfg>(striking_block(8), options());
  const std::string counts = message_of([&] { read_checkpoint(wider, path, ps_contact_cfg::name()); });
  CHECK(counts.find("35 particles, this problem has 40") != std::string::npos);
  auto lighter = make_solver<ps_contact_cfg>(striking_block(7, 7000.0), options());
  const std::string masses = message_of([&] { read_checkpoint(lighter, path, ps_contact_cfg::name()); });
  CHECK(masses.find("is of another problem: its particle masses differ") != std::string::npos);
  CHECK(lighter.steps() == 0);

  // A refused file leaves the solver as it was.
  CHECK(fresh.steps() == 0);
  CHECK(fresh.time() == 0.0);
  std::filesystem::remove_all(dir);
}

TEST_CASE("a checkpoint replaces the previous one through a temporary file") {
  test::run_serially();
  const auto dir = scratch_folder("replace");
  auto s = make_solver<axi_cfg>(compressed_cylinder(), options());
  const auto path = dir / "latest.rkpmcp";
  write_checkpoint(s, path, axi_cfg::name());
  s.step();
  write_checkpoint(s, path, axi_cfg::name());
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  CHECK(names == std::vector<std::string>{"latest.rkpmcp"});
  auto again = make_solver<axi_cfg>(compressed_cylinder(), options());
  read_checkpoint(again, path, axi_cfg::name());
  CHECK(again.steps() == 1);
  std::filesystem::remove_all(dir);
}

TEST_CASE("a checkpoint with any one bit flipped is refused, naming the damaged part") {
  test::run_serially();
  const auto dir = scratch_folder("damage");
  auto s = make_solver<ps_contact_cfg>(striking_block(), options());
  for (int k = 0; k < 40; ++k) s.step();
  REQUIRE(s.last_contact().active > 0);  // so that the contact pairs' section is not empty
  const auto good = dir / io::checkpoint_file_name(s.steps());
  write_checkpoint(s, good, ps_contact_cfg::name(), R"({"case": "striking_block"})");
  const std::string bytes = read_bytes(good);

  // The parts tile the file (no padding, no byte outside a checked part).
  const std::vector<file_part> parts = layout_of(bytes);
  bool tiled = parts.front().begin == 0 && parts.back().end == bytes.size();
  for (std::size_t k = 1; k < parts.size(); ++k) tiled = tiled && parts[k].begin == parts[k - 1].end;
  CHECK(tiled);
  CHECK(parts.size() > 20);

  // Every byte of the prefix, the header and the table (the file's last byte among them), the
  // first, middle and last byte of every section, and 600 pseudo-random places; the bit varies.
  std::vector<std::size_t> places;
  for (const file_part& p : parts) {
    if (p.name.starts_with("section"))
      for (std::size_t at : {p.begin, (p.begin + p.end) / 2, p.end - 1}) {
        if (p.begin < p.end) places.push_back(at);
      }
    else
      for (std::size_t at = p.begin; at < p.end; ++at) places.push_back(at);
  }
  std::mt19937_64 random(20240517);
  for (int k = 0; k < 600; ++k) places.push_back(random() % bytes.size());

  auto fresh = make_solver<ps_contact_cfg>(striking_block(), options());
  const auto path = dir / "damaged.rkpmcp";
  std::vector<std::string> wrong;
  std::set<std::string> named;
  for (std::size_t k = 0; k < places.size(); ++k) {
    const std::size_t at = places[k];
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ (1 << (k % 8)));
    std::ofstream(path, std::ios::binary | std::ios::trunc) << damaged;
    const file_part& part = *std::ranges::find_if(parts, [&](const file_part& p) { return at < p.end; });
    std::string message = "(no error)";
    bool typed = false;
    try {
      read_checkpoint(fresh, path, ps_contact_cfg::name());
    } catch (const io::checkpoint_damaged& e) {
      message = e.what();
      typed = true;
    } catch (const rkpm::error& e) {
      message = e.what();
    }
    const std::string expected = fmt::format("checkpoint '{}': {} fails its checksum: the file is damaged; restart "
                                             "from an earlier checkpoint",
                                             path.string(), part.name);
    if (!typed || message != expected)
      wrong.push_back(fmt::format("byte {} bit {} ({}): {}", at, k % 8, part.name, message));
    named.insert(part.name);
  }
  std::string first_wrong;
  for (std::size_t k = 0; k < wrong.size() && k < 5; ++k) first_wrong += "\n" + wrong[k];
  INFO(wrong.size(), " of ", places.size(), " refused wrongly or accepted:", first_wrong);
  CHECK(wrong.empty());
  std::size_t empty_sections = 0;
  for (const file_part& p : parts) empty_sections += p.begin == p.end;
  CHECK(named.size() + empty_sections == parts.size());  // every part was damaged somewhere
  CHECK(places.size() > 1000);
  CHECK(fresh.steps() == 0);  // no refused file changed the solver

  // The header alone (a restart's first read) refuses them too; the intact file still reads.
  std::string header_damaged = bytes;
  header_damaged[40] ^= 4;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << header_damaged;
  CHECK(message_of([&] { io::read_checkpoint_header(path); }).find("the header fails its checksum") != std::string::npos);
  read_checkpoint(fresh, good, ps_contact_cfg::name());
  CHECK(fresh.steps() == s.steps());
  std::filesystem::remove_all(dir);
}

}  // namespace test_unit_solver_checkpoint
