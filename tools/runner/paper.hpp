#pragma once
// `rkpm_run paper`: all three cases with Q2 and Q4, and a markdown report beside the paper's
// Table 3 (Taylor bar radius and height) and Table 5 (CPU-time reduction of Q2 against Q4).

namespace rkpm::runner {

int run_paper(int argc, char** argv);

}  // namespace rkpm::runner
