#pragma once
// `rkpm_run paper`: the chosen cases (default all) with Q2 and Q4, and a markdown report beside
// the paper's Table 3 (Taylor bar radius and height) and Table 5 (CPU-time reduction of Q2
// against Q4); then, beyond the paper, the same cases with the other rules (--rules).

#include "request.hpp"

namespace rkpm::runner {

int run_paper(const paper_request& o);

}  // namespace rkpm::runner
