// grainlab._grainlab: the compiled half of `import grainlab` (pybind11). It
// binds what the command line runs, never a second engine: configs are read,
// checked and written by io/config.h; a run is apps::run_lab, the function
// behind `grainlab run`; every other subcommand runs through
// apps::CommandLine, with the arguments a shell would give. The Python
// package (python/grainlab/) wraps these functions in its documented API.
//
// Threads and signals: run() releases the GIL while the engine steps. After
// each chunk of steps (about four a second, core/step_pacer.h) the run's
// hooks take the GIL back, call the progress callback and
// PyErr_CheckSignals(): a KeyboardInterrupt (Ctrl-C) or an exception of the
// callback makes the run save its checkpoint and stop, as SIGTERM does for the
// command line; run() then raises that exception.
#include "apps/command_line.h"
#include "apps/report.h"
#include "apps/run_lab.h"
#include "core/error.h"
#include "io/config.h"
#include "lab/lab_test.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

namespace py = pybind11;
using namespace grainlab;

namespace {

// Raises grainlab.errors.<name>(message): the Python classes carry file, key and fix.
void raise_python(const char* name, const std::string& message) {
  const py::object cls = py::module_::import("grainlab.errors").attr(name);
  PyErr_SetObject(cls.ptr(), py::str(message).ptr());
}

std::string config_toml(const std::string& text, const std::string& source) {
  return to_toml(parse_config(text, source));
}

std::string load_config_toml(const std::string& path) { return to_toml(load_config(path)); }

// The run's Python side: callbacks, and the first exception (a
// KeyboardInterrupt, or one a callback raised) that stops the run.
struct PythonHooks {
  py::object say, progress;
  std::optional<py::error_already_set> error;

  // With the GIL: was a signal raised, or did a callback fail? Keeps the first exception.
  bool failed() {
    if (error) return true;
    if (PyErr_CheckSignals() != 0) error.emplace();
    return error.has_value();
  }
  std::string stop_reason() {
    py::gil_scoped_acquire gil;
    if (!failed()) return {};
    return error->matches(PyExc_KeyboardInterrupt) ? std::string("KeyboardInterrupt")
                                                    : fmt::format("an exception in Python ({})", error->what());
  }
  void call(const py::object& f, const py::object& arg) {
    py::gil_scoped_acquire gil;
    if (f.is_none() || error) return;
    try {
      f(arg);
    } catch (py::error_already_set& e) {
      error.emplace(std::move(e));
    }
  }
};

py::dict progress_dict(const apps::RunProgress& p) {
  py::dict d;
  d["phase"] = p.phase;
  d["step"] = p.step;
  d["time_s"] = p.time_s;
  d["loading"] = p.loading;
  d["progress"] = p.progress;
  d["final_progress"] = p.final_progress;
  d["progress_label"] = p.progress_label;
  d["status"] = p.status;
  return d;
}

int run(const std::string& toml_text, const std::string& source, const std::string& out, bool resume, int threads,
        const py::object& progress, const py::object& say, bool report, const std::string& resume_hint) {
  LabSpec spec = parse_config(toml_text, source);
  if (!out.empty()) spec.output.folder = out;
  PythonHooks py_hooks{say, progress, std::nullopt};
  apps::RunHooks hooks;
  hooks.say = [&](std::string_view line) { py_hooks.call(py_hooks.say, py::str(std::string(line))); };
  hooks.stop_reason = [&] { return py_hooks.stop_reason(); };
  hooks.progress = [&](const apps::RunProgress& p) {
    if (py_hooks.progress.is_none()) return;
    py::gil_scoped_acquire gil;
    py_hooks.call(py_hooks.progress, progress_dict(p));
  };
  hooks.status_lines = !say.is_none();
  hooks.report = report;
  hooks.resume_hint = resume_hint;
  int rc = 0;
  {
    py::gil_scoped_release nogil;
    rc = apps::run_lab(spec, resume, threads, hooks);
  }
  if (py_hooks.error) throw std::move(*py_hooks.error);
  return rc;
}

// Standard output of this process (file descriptor 1) sent to a temporary
// file while it lives; text() reads what was written.
class CapturedStdout {
 public:
  CapturedStdout() {
    std::fflush(stdout);
    file_ = std::tmpfile();
    if (!file_) throw RunError("cannot create a temporary file to capture a command's output: check the space in /tmp");
    saved_ = ::dup(1);
    ::dup2(::fileno(file_), 1);
  }
  ~CapturedStdout() {
    restore();
    if (file_) std::fclose(file_);
  }
  std::string text() {
    restore();
    std::string s;
    std::rewind(file_);
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, file_)) > 0) s.append(buf, n);
    return s;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stdout);
    ::dup2(saved_, 1);
    ::close(saved_);
    saved_ = -1;
  }
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

// The handlers of the signals a subcommand takes over (`grains index` turns
// SIGINT into a kept preparation), put back when this goes out of scope: the
// Python process keeps its own (Ctrl-C is KeyboardInterrupt again).
class KeptSignalHandlers {
 public:
  KeptSignalHandlers() {
    for (std::size_t k = 0; k < kSignals.size(); ++k) ::sigaction(kSignals[k], nullptr, &saved_[k]);
  }
  ~KeptSignalHandlers() {
    for (std::size_t k = 0; k < kSignals.size(); ++k) ::sigaction(kSignals[k], &saved_[k], nullptr);
  }

 private:
  static constexpr std::array<int, 4> kSignals = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ};
  std::array<struct sigaction, 4> saved_{};
};

// `grainlab ARGS...` in this process: (exit code, standard output when captured, else "").
std::pair<int, std::string> command(const std::vector<std::string>& args, bool capture) {
  apps::CommandLine command_line;
  std::vector<std::string> argv_text = {"grainlab"};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<const char*> argv;
  for (const std::string& a : argv_text) argv.push_back(a.c_str());
  try {
    command_line.app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    throw InputError(fmt::format("grainlab {}: {}", fmt::join(args, " "), e.what()));
  }
  std::optional<CapturedStdout> captured;
  if (capture) captured.emplace();
  int rc = 0;
  {
    const KeptSignalHandlers kept;
    py::gil_scoped_release nogil;
    rc = command_line.run();
  }
  return {rc, captured ? captured->text() : std::string()};
}

}  // namespace

PYBIND11_MODULE(_grainlab, m) {
  m.doc() = "grainlab's compiled core: the command line's config, run and subcommand functions. Use the "
            "documented API of the grainlab package (help(grainlab)), which wraps these.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      raise_python("ConfigError", e.what());
    } catch (const RunError& e) {
      raise_python("RunError", e.what());
    } catch (const Stopped& e) {
      raise_python("RunError", e.what());
    }
  });
  m.def("config_toml", &config_toml, py::arg("text"), py::arg("source"),
        "Parses and checks config text as `grainlab run` does (source: the name in messages); returns every key as "
        "TOML. Raises grainlab.ConfigError with the command line's message.");
  m.def("load_config_toml", &load_config_toml, py::arg("path"),
        "Reads, parses and checks a config file as `grainlab run FILE` does; returns every key as TOML.");
  m.def(
      "default_config_toml",
      [](const std::string& test, const std::string& law) {
        return default_config_toml(test, law.empty() ? ContactLaw{} : parse_contact_law(law));
      },
      py::arg("test"), py::arg("law") = "",
      "The commented default config of a lab test (`grainlab run --print-defaults --test TEST`).");
  m.def(
      "config_differences",
      [](const std::string& a, const std::string& b) {
        return config_differences(parse_config(a, "a"), parse_config(b, "b"));
      },
      py::arg("a"), py::arg("b"), "Dotted keys whose values differ between two config texts.");
  m.def("lab_test_names", &lab_test_names, "The registered lab tests (direct-shear, oedometer, triaxial, ...).");
  m.def("run", &run, py::arg("toml_text"), py::arg("source"), py::arg("out"), py::arg("resume"), py::arg("threads"),
        py::arg("progress"), py::arg("say"), py::arg("report"), py::arg("resume_hint"),
        "Runs a lab test as `grainlab run` does (apps::run_lab) with the GIL released; 0 when it finished, 130 when "
        "a KeyboardInterrupt or a callback's exception stopped it (a checkpoint is saved; the exception is then "
        "raised).");
  m.def("prepare_report_folder", &apps::prepare_report_folder, py::arg("runs"), py::arg("out"),
        "The report's output folder for these run folders and --out ('': the default), after writing what the "
        "engine computes for it (several triaxial runs: mohr_coulomb.json there, the Mohr-Coulomb fit), as "
        "`grainlab report` does before it runs grainlab.report.");
  m.def("command", &command, py::arg("args"), py::arg("capture") = false,
        "Runs `grainlab ARGS...` in this process; returns (exit code, standard output if capture else ''). A "
        "subcommand stopped by Ctrl-C returns 130, having kept what it could.");
}
