// Consumer of the optional component gnuplot: <rkpm/io/gnuplot.hpp> through rkpm::gnuplot. Built
// (and so linked against gnuplot-iostream's Boost libraries) by the packaging test; with an
// output path it also draws a small figure.
#include <cstdio>
#include <utility>
#include <vector>

#include <rkpm/io/gnuplot.hpp>

int main(int argc, char** argv) {
  if (argc < 2) return 0;
  try {
    rkpm::io::gnuplot_figure fig(argv[1], {.width = 320, .height = 240});
    fig << "plot '-' using 1:2 with lines notitle\n";
    fig.send1d(std::vector<std::pair<double, double>>{{0.0, 0.0}, {1.0, 1.0}});
    fig.render();
    return 0;
  } catch (const rkpm::error& e) {
    std::printf("rkpm consumer plot: %s\n", e.what());
    return 1;
  }
}
