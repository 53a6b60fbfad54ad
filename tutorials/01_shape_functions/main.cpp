// Tutorial 01: RK shape functions.
//
// ---------------------------------------------------------------------------------------
// Introduction
// ---------------------------------------------------------------------------------------
// Every later program in rkpm rests on one formula (docs/method.md (2), (11)):
//
//   N_I(x) = H(0)^T M(x)^-1 H((x - x_I)/s) Phi_a(x - x_I) dV_I
//   M(x)   = sum_J H((x - x_J)/s) H((x - x_J)/s)^T Phi_a(x - x_J) dV_J
//
// A kernel Phi_a (a smooth bump of support a around each particle) is multiplied by a
// correction, a polynomial whose coefficients are chosen point by point so that the shape
// functions reproduce every polynomial of the basis H exactly: sum_I N_I(x) p(x_I) = p(x).
// Two choices make an RK approximation:
//   - the kernel profile: rkpm::kernel::cubic_spline or rkpm::kernel::quartic_spline;
//   - the correction order: rkpm::correction::linear (1, x, y) or ::quadratic (adds x^2, xy, y^2).
//
// This program builds a 1D and a 2D particle set, evaluates the shape functions of one
// particle on the boundary and one in the interior for all four combinations, writes the
// numbers as CSV and plots them with gnuplot. The README explains what the pictures show.
//
// Usage: tutorial_01_shape_functions [output directory]   (default results/01_shape_functions)

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <rkpm/correction/polynomial_bases.hpp>
#include <rkpm/approximation/rk_shape_functions.hpp>
#include <rkpm/discretization/neighbor_search.hpp>
#include <rkpm/discretization/particle_set.hpp>
#include <rkpm/kernel/cubic_spline.hpp>
#include <rkpm/kernel/quartic_spline.hpp>
#include <rkpm/io/gnuplot.hpp>

namespace fs = std::filesystem;
using rkpm::index_t;
using rkpm::vec;

// ---------------------------------------------------------------------------------------
// Plotting with gnuplot
// ---------------------------------------------------------------------------------------
// rkpm::io::gnuplot_png runs gnuplot with the cairo terminal (or libgd's `png` where cairo
// is missing) and checks that a PNG came out; a failing script is kept as <name>.png.gp.
namespace plot {

void png(const fs::path& dir, const std::string& name, const std::string& body, int width,
         int height) {
  const fs::path png_file = dir / (name + ".png");
  try {
    rkpm::io::gnuplot_png(png_file, body, {.width = width, .height = height, .font = "Sans,10"});
    std::cout << "  wrote " << png_file.string() << "\n";
  } catch (const rkpm::error& e) {
    std::cout << "  could not plot " << png_file.string() << ": " << e.what() << "; the CSV data is there\n";
  }
}

}  // namespace plot

// ---------------------------------------------------------------------------------------
// Evaluating one particle's shape function along a list of points
// ---------------------------------------------------------------------------------------
// rk_shape_functions<K, C, Dim>::evaluate works point by point: for a point x it needs the
// particles whose support covers x (from the neighbor search) and returns N_J(x) for exactly
// those. To draw the function of one particle I we evaluate at many points and pick I out of
// each neighbor list (N_I(x) = 0 where I is not a neighbor).
template <class K, class C, int Dim>
std::vector<double> shape_function_of(index_t I, const rkpm::particle_set<Dim>& particles,
                                      const std::vector<vec<Dim>>& points) {
  const rkpm::neighbor_search<Dim> search(particles);
  const rkpm::rk_shape_functions<K, C, Dim> rk;
  std::vector<index_t> neighbors;
  std::vector<double> N;
  std::vector<vec<Dim>> grad;
  std::vector<double> out(points.size(), 0.0);
  for (std::size_t p = 0; p < points.size(); ++p) {
    search.query(points[p], neighbors);
    rk.evaluate(points[p], particles, neighbors, N, grad);
    for (std::size_t j = 0; j < neighbors.size(); ++j)
      if (neighbors[j] == I) out[p] = N[j];
  }
  return out;
}

// The largest deviation from partition of unity, sum_J N_J(x) = 1, over the points: a check
// that the program is drawing what the theory says.
template <class K, class C, int Dim>
double partition_of_unity_error(const rkpm::particle_set<Dim>& particles,
                                const std::vector<vec<Dim>>& points) {
  const rkpm::neighbor_search<Dim> search(particles);
  const rkpm::rk_shape_functions<K, C, Dim> rk;
  std::vector<index_t> neighbors;
  std::vector<double> N;
  std::vector<vec<Dim>> grad;
  double worst = 0.0;
  for (const auto& x : points) {
    search.query(x, neighbors);
    rk.evaluate(x, particles, neighbors, N, grad);
    double sum = 0.0;
    for (double n : N) sum += n;
    worst = std::max(worst, std::abs(sum - 1.0));
  }
  return worst;
}

// Support factors s in a = s h. The linear basis needs at least 2 particles per direction
// under every point's supports, the quadratic basis 3; in 2D, s = 2 and s = 2.5 leave margin
// at the boundary, where a point only sees particles on one side (the values the tests use).
template <class C>
constexpr double support_factor = C::order == 1 ? 2.0 : 2.5;

// In 1D we take half a spacing more (s = 2.5 and 3.5). With s = 2 exactly, the end point
// x = 0 is covered by just two particles (the one at 2h sits on the support edge, where the
// window vanishes); a linear fit through two points is unique, so N_0(0) = 1 and N_1(0) = 0
// there, an accident of counting that hides the non-interpolating nature of RK. One more
// particle under the end point shows the general case.
template <class C>
constexpr double support_factor_1d = C::order == 1 ? 2.5 : 3.5;

// ---------------------------------------------------------------------------------------
// The program
// ---------------------------------------------------------------------------------------
class shape_functions_tutorial {
 public:
  explicit shape_functions_tutorial(fs::path out) : out_(std::move(out)) {}

  void run() {
    fs::create_directories(out_);
    std::cout << "Tutorial 01: RK shape functions; output in " << out_.string() << "\n";
    kernel_profiles();
    shape_functions_1d();
    shape_functions_2d();
    std::cout << "done: figures and CSV files are in " << fs::absolute(out_).string() << "\n";
  }

 private:
  // ---- Step 1: the two kernel profiles -------------------------------------------------
  // phi(z) on [-1, 1], unit integral; the 2D window is phi(x/a_x) phi(y/a_y) / (a_x a_y).
  // The cubic B-spline is flatter near its edges (knots at |z| = 1/2), the quartic spline
  // has a slightly lower, broader peak.
  void kernel_profiles() {
    std::cout << "Step 1: kernel profiles\n";
    const fs::path csv = out_ / "kernels.csv";
    std::ofstream f(csv);
    f << "z,cubic,quartic,d_cubic,d_quartic\n";
    for (int i = 0; i <= 400; ++i) {
      const double z = -1.1 + 2.2 * i / 400.0;
      f << fmt::format("{},{},{},{},{}\n", z, rkpm::kernel::cubic_spline::value(z),
                       rkpm::kernel::quartic_spline::value(z),
                       rkpm::kernel::cubic_spline::derivative(z),
                       rkpm::kernel::quartic_spline::derivative(z));
    }
    f.close();
    std::cout << "  wrote " << csv.string() << "\n";
    plot::png(out_, "kernels", fmt::format(R"gp(set datafile separator ','
set key autotitle columnhead
set multiplot layout 1,2
set grid
set xlabel 'z = x / a'
set title 'kernel profile {{/Symbol f}}(z)'
plot '{0}' using 1:2 with lines lw 2 title 'cubic spline', \
     '{0}' using 1:3 with lines lw 2 dt 2 title 'quartic spline'
set title "derivative {{/Symbol f}}'(z)"
plot '{0}' using 1:4 with lines lw 2 title 'cubic spline', \
     '{0}' using 1:5 with lines lw 2 dt 2 title 'quartic spline'
unset multiplot
)gp", csv.string()),
              1000, 420);
  }

  // ---- Step 2: 1D, 11 particles on [0, 1] ----------------------------------------------
  // make_grid_particles gives spacing h = 0.1, support a = s h and tributary volumes
  // (h/2 at the ends). We draw N_0 (the particle at x = 0, on the boundary) and N_5 (the one
  // at x = 0.5, in the interior). Dim = 1 uses the same classes as the 2D solver.
  void shape_functions_1d() {
    std::cout << "Step 2: 1D shape functions, 11 particles on [0, 1]\n";
    std::vector<vec<1>> xs;
    for (int i = 0; i <= 1000; ++i) xs.emplace_back(i / 1000.0);

    using namespace rkpm::kernel;
    using namespace rkpm::correction;
    std::vector<std::vector<double>> columns;
    std::vector<std::string> names;
    auto add = [&]<class K, class C>(K, C) {
      const auto particles = rkpm::make_grid_particles<1>(vec<1>(0.0), vec<1>(1.0),
                                                          Eigen::Matrix<int, 1, 1>(11),
                                                          support_factor_1d<C>);
      columns.push_back(shape_function_of<K, C, 1>(0, particles, xs));
      columns.push_back(shape_function_of<K, C, 1>(5, particles, xs));
      names.push_back(fmt::format("{}_{}_boundary", K::name, C::name));
      names.push_back(fmt::format("{}_{}_interior", K::name, C::name));
      // The boundary particle's value at its own position: not 1 (RK is not interpolating).
      std::cout << fmt::format(
          "  {:7} + {:9} (s = {}): N_0(x_0) = {:.4f}, N_5(x_5) = {:.4f}, "
          "max |sum N - 1| = {:.1e}\n",
          K::name, C::name, support_factor_1d<C>, columns[columns.size() - 2][0],
          columns.back()[500], partition_of_unity_error<K, C, 1>(particles, xs));
    };
    add(cubic_spline{}, linear{});
    add(cubic_spline{}, quadratic{});
    add(quartic_spline{}, linear{});
    add(quartic_spline{}, quadratic{});

    const fs::path csv = out_ / "shape_1d.csv";
    std::ofstream f(csv);
    f << "x";
    for (const auto& n : names) f << "," << n;
    f << "\n";
    for (std::size_t p = 0; p < xs.size(); ++p) {
      f << xs[p][0];
      for (const auto& c : columns) f << "," << fmt::format("{:.12g}", c[p]);
      f << "\n";
    }
    f.close();
    std::cout << "  wrote " << csv.string() << "\n";

    // Columns: 2..5 cubic (linear b/i, quadratic b/i), 6..9 quartic.
    for (const auto& [order, col] : {std::pair{"linear", 2}, std::pair{"quadratic", 4}}) {
      plot::png(out_, fmt::format("shape_1d_{}", order), fmt::format(R"gp(set datafile separator ','
set grid
set xlabel 'x'
set ylabel 'N_I(x)'
set title '1D RK shape functions, {0} correction (11 particles, h = 0.1, a = {1} h)'
set key top right
set xrange [0:1]
set yrange [-0.1:1.05]
set arrow from 0,0 to 1,0 nohead lc rgb 'gray'
$particles << EOD
0,0
0.1,0
0.2,0
0.3,0
0.4,0
0.5,0
0.6,0
0.7,0
0.8,0
0.9,0
1,0
EOD
plot '{2}' using 1:{3} with lines lw 2 lc rgb '#1f77b4' title 'boundary I = 0, cubic', \
     '{2}' using 1:{5} with lines lw 2 dt 2 lc rgb '#1f77b4' title 'boundary I = 0, quartic', \
     '{2}' using 1:{4} with lines lw 2 lc rgb '#d62728' title 'interior I = 5, cubic', \
     '{2}' using 1:{6} with lines lw 2 dt 2 lc rgb '#d62728' title 'interior I = 5, quartic', \
     $particles using 1:2 with points pt 7 ps 0.8 lc rgb 'black' title 'particles'
)gp", order, order == std::string("linear") ? 2.5 : 3.5, csv.string(), col, col + 1, col + 4,
                                             col + 5),
                900, 560);
    }
  }

  // ---- Step 3: 2D, 11 x 11 particles on [0, 1]^2 ----------------------------------------
  // The same construction with a tensor-product window. We draw N_I over the square for the
  // particle at (0, 0.5) on the left edge and the particle at (0.5, 0.5) in the middle.
  void shape_functions_2d() {
    std::cout << "Step 3: 2D shape functions, 11 x 11 particles on [0, 1]^2\n";
    const int n = 161;
    std::vector<rkpm::vec2> xs;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) xs.emplace_back(i / (n - 1.0), j / (n - 1.0));
    // make_grid_particles numbers particles with x fastest: index = i + 11 j.
    const index_t boundary = 0 + 11 * 5, interior = 5 + 11 * 5;

    using namespace rkpm::kernel;
    using namespace rkpm::correction;
    std::vector<std::string> panels_boundary, panels_interior;
    double lo = 0.0, hi = 0.0;  // colour range over all panels, so they compare directly
    auto add = [&]<class K, class C>(K, C) {
      const auto particles = rkpm::make_grid_particles<2>(rkpm::vec2(0, 0), rkpm::vec2(1, 1),
                                                          {11, 11}, support_factor<C>);
      for (const auto& [I, where, panels] :
           {std::tuple{boundary, "boundary", &panels_boundary},
            std::tuple{interior, "interior", &panels_interior}}) {
        const auto N = shape_function_of<K, C, 2>(I, particles, xs);
        lo = std::min(lo, *std::min_element(N.begin(), N.end()));
        hi = std::max(hi, *std::max_element(N.begin(), N.end()));
        const fs::path csv = out_ / fmt::format("shape_2d_{}_{}_{}.csv", where, K::name, C::name);
        std::ofstream f(csv);
        f << "# x,y,N\n";
        for (int i = 0; i < n; ++i) {
          for (int j = 0; j < n; ++j) {
            const std::size_t p = static_cast<std::size_t>(i * n + j);
            f << fmt::format("{},{},{:.12g}\n", xs[p][0], xs[p][1], N[p]);
          }
          f << "\n";  // gnuplot grid format: a blank line after each scan line
        }
        std::cout << fmt::format("  {:8} particle, {:7} + {:9}: N_I(x_I) = {:.4f}, min N_I = {:.4f}\n",
                                 where, K::name, C::name, N[particles_index(I, n)],
                                 *std::min_element(N.begin(), N.end()));
        panels->push_back(fmt::format(
            "set title '{} + {} (a = {} h)'\nsplot '{}' using 1:2:3 with pm3d notitle\n", K::name,
            C::name, support_factor<C>, csv.string()));
      }
      std::cout << fmt::format("  {:7} + {:9}: max |sum N - 1| over the square = {:.1e}\n",
                               K::name, C::name, partition_of_unity_error<K, C, 2>(particles, xs));
    };
    add(cubic_spline{}, linear{});
    add(cubic_spline{}, quadratic{});
    add(quartic_spline{}, linear{});
    add(quartic_spline{}, quadratic{});

    // Each figure zooms on the particle's support (plus a margin).
    for (const auto& [where, panels, pos, x0] :
         {std::tuple{"boundary", &panels_boundary, "(0, 0.5)", 0.0},
          std::tuple{"interior", &panels_interior, "(0.5, 0.5)", 0.2}}) {
      std::string body = fmt::format(R"gp(set datafile separator ','
set view map
set size ratio -1
set xrange [{5}:{5} + 0.6]
set yrange [0.2:0.8]
set xlabel 'x'
set ylabel 'y'
set palette defined ({2} '#2166ac', 0 'white', {3} '#fdae61', {4} '#b2182b')
set cbrange [{2}:{4}]
set multiplot layout 2,2 title 'N_I for the {0} particle at {1} (11 x 11 particles; blue < 0 < red)'
)gp",
                                     where, pos, lo, 0.3 * hi, hi, x0);
      for (const auto& p : *panels) body += p;
      body += "unset multiplot\n";
      plot::png(out_, fmt::format("shape_2d_{}", where), body, 1000, 950);
    }
  }

  // Index in the evaluation grid (x slowest, spacing 1/(n-1)) of the grid particle I
  // (11 x 11, spacing 1/10, x fastest).
  static std::size_t particles_index(index_t I, int n) {
    const int i = static_cast<int>(I % 11), j = static_cast<int>(I / 11);
    const int step = (n - 1) / 10;
    return static_cast<std::size_t>(i * step * n + j * step);
  }

  fs::path out_;
};

int main(int argc, char** argv) {
  try {
    shape_functions_tutorial(argc > 1 ? argv[1] : "results/01_shape_functions").run();
  } catch (const std::exception& e) {
    std::cerr << "tutorial_01_shape_functions: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
