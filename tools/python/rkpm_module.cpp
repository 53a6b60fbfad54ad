// The Python module `rkpm` (pybind11): rkpm.run(...) runs a paper case or a case file exactly as
// `rkpm_run` does (the same parser, checks, solvers and outputs: this module links the runner's
// library) and hands back the summary, the history and the particles as NumPy arrays. See
// tools/python/README.md for the interface; tests/python/test_rkpm.py tests it.
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include <unistd.h>

#include <rkpm/core/error.hpp>
#include <rkpm/solver/method_names.hpp>

#include "case_list.hpp"
#include "interrupt.hpp"
#include "methods.hpp"
#include "outcome.hpp"
#include "request.hpp"
#include "run_case_file.hpp"

namespace py = pybind11;
namespace runner = rkpm::runner;

namespace {

// Raised as rkpm.CaseError (a request, case file or parameter the runner refuses) and
// rkpm.RunError (a run that failed after its set-up); both are rkpm.Error.
struct case_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct run_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct any_error {};  // the tag of rkpm.Error, the base of both

// A --set value from a Python value: strings as they are, anything else as JSON (numbers,
// booleans, lists and objects for JSON-pointer settings of case files).
std::string set_value(const py::handle& value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  return py::module_::import("json").attr("dumps")(value).cast<std::string>();
}

// A dict case is written to a case file of its own (named by its "name", in a scratch folder)
// and run from there; its relative paths (Gmsh meshes) are then relative to the current folder,
// which is where they are looked for first (tools/python/README.md).
std::string case_argument(const py::object& c) {
  if (py::isinstance<py::str>(c) || py::isinstance(c, py::module_::import("pathlib").attr("PurePath"))) {
    std::string s = py::str(c).cast<std::string>();
    if (s.ends_with(".json")) s = std::filesystem::absolute(s).string();
    return s;
  }
  if (!py::isinstance<py::dict>(c))
    throw case_error("rkpm.run: case must be a case name (rkpm.cases), a case file's path or a dict with a case "
                     "file's content");
  const py::dict d = c.cast<py::dict>();
  const std::string name = d.contains("name") ? py::str(d["name"]).cast<std::string>() : std::string("case");
  static int count = 0;
  const auto dir = std::filesystem::temp_directory_path() / ("rkpm_python_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / (name + "_" + std::to_string(++count) + ".json");
  std::ofstream(file) << py::module_::import("json").attr("dumps")(d, py::arg("indent") = 2).cast<std::string>();
  return file.string();
}

// NumPy copies of a particle state: positions (N x 2), vectors (N x 2), the Cauchy stress
// (N x 4: xx, yy, zz, xy; zz is the hoop stress in axisymmetric runs), scalars (N). The
// observer's arrays are read-only.
py::object state_namespace(const runner::particle_state& s, bool read_only) {
  const auto n = static_cast<py::ssize_t>(s.positions.size());
  py::dict fields;
  const auto finish = [&](py::array_t<double> a) {
    if (read_only) a.attr("flags").attr("writeable") = false;
    return a;
  };
  py::array_t<double> positions({n, py::ssize_t{2}});
  for (py::ssize_t i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) positions.mutable_at(i, k) = s.positions[i][k];
  fields["positions"] = finish(positions);
  for (const auto& a : s.fields.arrays()) {
    py::array_t<double> out;
    if (a.components == 1) {
      out = py::array_t<double>(n, a.values.data());
    } else if (a.components == 3) {  // (x, y, 0)
      out = py::array_t<double>({n, py::ssize_t{2}});
      for (py::ssize_t i = 0; i < n; ++i)
        for (int k = 0; k < 2; ++k) out.mutable_at(i, k) = a.values[3 * i + k];
    } else if (a.components == 9) {  // row-major 3 x 3
      out = py::array_t<double>({n, py::ssize_t{4}});
      for (py::ssize_t i = 0; i < n; ++i) {
        const double* m = &a.values[9 * i];
        out.mutable_at(i, 0) = m[0];
        out.mutable_at(i, 1) = m[4];
        out.mutable_at(i, 2) = m[8];
        out.mutable_at(i, 3) = m[1];
      }
    } else {
      continue;
    }
    fields[py::str(a.name)] = finish(out);
  }
  if (fields.contains("equivalent_plastic_strain")) fields["plastic_strain"] = fields["equivalent_plastic_strain"];
  fields["time_s"] = s.time_s;
  fields["step"] = s.step;
  return py::module_::import("types").attr("SimpleNamespace")(**fields);
}

// For one run: Ctrl-C and SIGTERM stop it between two steps (the runner's own handler,
// interrupt.hpp); restored after it with the thread count.
struct process_settings {
#ifdef _OPENMP
  int threads = omp_get_max_threads();
#endif
  void (*sigint)(int) = std::signal(SIGINT, runner::record_interrupt);
  void (*sigterm)(int) = std::signal(SIGTERM, runner::record_interrupt);
  ~process_settings() {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    std::signal(SIGINT, sigint);
    std::signal(SIGTERM, sigterm);
    runner::pending_interrupt() = 0;
  }
};

py::object run(const py::object& case_, const py::dict& set, std::optional<int> resolution,
               std::optional<std::string> quadrature, std::optional<std::string> kernel,
               std::optional<std::string> correction, std::optional<std::string> contact, std::optional<int> threads,
               std::optional<double> end_time, std::optional<std::string> out, const py::object& observe, long every,
               bool plots, bool quiet) {
  std::vector<std::string> args{"rkpm_run", case_argument(case_)};
  const auto option = [&](const char* name, const auto& value) {
    if (value) {
      args.emplace_back(name);
      args.push_back(fmt::format("{}", *value));
    }
  };
  option("--resolution", resolution);
  option("--quadrature", quadrature);
  option("--kernel", kernel);
  option("--correction", correction);
  option("--enforcement", contact);
  option("--out", out);
  if (end_time) args.insert(args.end(), {"--end-time", fmt::format("{:.17g}", *end_time)});
  if (!plots) args.emplace_back("--no-plots");
  if (quiet) args.emplace_back("--quiet");
  for (const auto& [k, v] : set) args.insert(args.end(), {"--set", py::str(k).cast<std::string>() + "=" + set_value(v)});
  if (every < 1) throw case_error(fmt::format("rkpm.run: every = {} must be at least 1", every));

  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  runner::command_line cl;
  try {
    cl = runner::parse_command_line(static_cast<int>(argv.size()), argv.data());
  } catch (const std::exception& e) {
    throw case_error(e.what());
  }
  if (cl.what != runner::command_line::action::run)
    throw case_error("rkpm.run: runs one case; use the command line (tools/rkpm paper) for the paper");
  runner::run_request r = cl.run;
  r.hooks.keep_final_state = true;
  std::optional<py::error_already_set> observer_error;
  if (!observe.is_none()) {
    r.hooks.every = every;
    r.hooks.observe = [&](const runner::particle_state& s) {
      py::gil_scoped_acquire gil;
      try {
        const py::object answer = observe(state_namespace(s, true));
        return answer.is_none() || py::bool_(answer).cast<bool>();
      } catch (py::error_already_set& e) {
        observer_error.emplace(std::move(e));
        return false;
      }
    };
  }

  runner::run_outcome outcome;
  std::optional<std::string> failure, refusal;
  bool interrupted = false;
  {
    process_settings restore;
#ifdef _OPENMP
    if (threads && *threads > 0) omp_set_num_threads(*threads);
#endif
    py::gil_scoped_release no_gil;
    try {
      outcome = r.case_file.empty() ? runner::run_named_case(r) : runner::run_case_file(r);
    } catch (const runner::run_failure& e) {
      failure = e.what();
    } catch (const std::exception& e) {
      refusal = e.what();
    }
    interrupted = runner::pending_interrupt().load() != 0;
  }
  if (observer_error) throw std::move(*observer_error);
  if (interrupted) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  if (failure) throw run_error(*failure);
  if (refusal) throw case_error(*refusal);

  py::dict history;
  for (std::size_t c = 0; c < outcome.history.columns.size(); ++c) {
    py::array_t<double> column(static_cast<py::ssize_t>(outcome.history.rows.size()));
    for (std::size_t i = 0; i < outcome.history.rows.size(); ++i) column.mutable_at(i) = outcome.history.rows[i][c];
    history[py::str(outcome.history.columns[c])] = column;
  }
  py::object result = state_namespace(*outcome.final_state, false);
  result.attr("summary") = py::module_::import("json").attr("loads")(outcome.summary.dump());
  result.attr("history") = history;
  result.attr("directory") = outcome.directory;
  result.attr("completed") = outcome.completed;
  return result;
}

}  // namespace

PYBIND11_MODULE(rkpm, m) {
  m.doc() = "rkpm: the Reproducing Kernel Particle Method runner (tools/python/README.md)";
  const py::exception<any_error> base(m, "Error", PyExc_RuntimeError);
  py::register_exception<case_error>(m, "CaseError", base.ptr());
  py::register_exception<run_error>(m, "RunError", base.ptr());
  m.def("run", &run, py::arg("case"), py::kw_only(), py::arg("set") = py::dict(), py::arg("resolution") = py::none(),
        py::arg("quadrature") = py::none(), py::arg("kernel") = py::none(), py::arg("correction") = py::none(),
        py::arg("contact") = py::none(), py::arg("threads") = py::none(), py::arg("end_time") = py::none(),
        py::arg("out") = py::none(), py::arg("observe") = py::none(), py::arg("every") = 1,
        py::arg("plots") = true, py::arg("quiet") = true,
        "Runs a case (a name of rkpm.cases, a case file's path, or a dict with a case file's content) as "
        "rkpm_run does; returns the summary, history and final particles. See tools/python/README.md.");
  m.attr("cases") = runner::case_names();
  m.attr("kernels") = rkpm::policy_names(runner::kernels);
  m.attr("corrections") = rkpm::policy_names(runner::corrections);
  m.attr("quadratures") = rkpm::policy_names(runner::quadratures);
  m.attr("contacts") = rkpm::policy_names(runner::enforcements);
}
