#include "app/cli.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "core/text.h"
#include "sim/openap_data.h"

namespace squawk::app {

Result<Args> Args::parse(const std::vector<std::string>& argv, const Spec& spec) {
  Args a;
  auto is_in = [](const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
  };
  for (size_t i = 0; i < argv.size(); ++i) {
    const std::string& t = argv[i];
    if (t == "--") {
      a.positional_.insert(a.positional_.end(), argv.begin() + static_cast<long>(i) + 1, argv.end());
      break;
    }
    if (t.size() > 2 && t.rfind("--", 0) == 0) {
      std::string name = t, value;
      bool has_value = false;
      if (auto eq = t.find('='); eq != std::string::npos) {
        name = t.substr(0, eq);
        value = t.substr(eq + 1);
        has_value = true;
      }
      if (is_in(spec.value_flags, name)) {
        if (!has_value) {
          if (i + 1 >= argv.size())
            return Status::invalid("flag " + name + " needs a value");
          value = argv[++i];
        }
        a.values_[name] = value;
        continue;
      }
      if (is_in(spec.bool_flags, name)) {
        if (has_value) return Status::invalid("flag " + name + " takes no value");
        a.values_[name] = "1";
        continue;
      }
      if (!spec.pass_unknown) {
        std::vector<std::string> known = spec.value_flags;
        known.insert(known.end(), spec.bool_flags.begin(), spec.bool_flags.end());
        std::sort(known.begin(), known.end());
        known.erase(std::unique(known.begin(), known.end()), known.end());
        return Status::invalid("unknown flag " + text::quoted(name) + "; known: " +
                               (known.empty() ? std::string("none") : text::join(known, " ")));
      }
    }
    a.positional_.push_back(t);
  }
  return a;
}

std::optional<std::string> Args::get(const std::string& flag) const {
  auto it = values_.find(flag);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

std::string Args::get_or(const std::string& flag, const std::string& fallback) const {
  auto v = get(flag);
  return v ? *v : fallback;
}

Result<long long> Args::get_int(const std::string& flag, long long fallback) const {
  auto v = get(flag);
  if (!v) return fallback;
  auto n = text::to_int(*v);
  if (!n) return Status::invalid("flag " + flag + " expects an integer, got " + text::quoted(*v));
  return *n;
}

Result<double> Args::get_double(const std::string& flag, double fallback) const {
  auto v = get(flag);
  if (!v) return fallback;
  auto n = text::to_double(*v);
  if (!n) return Status::invalid("flag " + flag + " expects a number, got " + text::quoted(*v));
  return *n;
}

int usage_error(const std::string& subcommand, const std::string& message) {
  std::fprintf(stderr, "squawk %s: %s\n(see `squawk help %s`)\n", subcommand.c_str(), shown_error(message).c_str(),
               subcommand.c_str());
  return kExitUsage;
}

namespace {
bool g_verbose = false;
}  // namespace

void set_verbose(bool on) { g_verbose = on; }

std::string shown_error(const std::string& message) {
  if (g_verbose) return message;
  return message.substr(0, message.find("\nstack traceback:"));
}

int failure(const Status& st) {
  std::fprintf(stderr, "squawk: %s\n", shown_error(st.message()).c_str());
  return kExitFail;
}

namespace {

void print_main_help() {
  std::printf(
      "squawk %s: an LLM-manned team for air traffic control, in one C++ engine scripted in Lua.\n\n"
      "usage: squawk [--help] [--version] SUBCOMMAND [ARGS...]\n\n"
      "subcommands:\n",
      SQUAWK_VERSION);
  for (const auto& s : subcommands()) std::printf("  %s\n", s.synopsis);
  std::printf("\n`squawk help SUBCOMMAND` explains one subcommand. Every subcommand also takes --openap DIR\n"
              "(OpenAP performance data) and --verbose (Lua errors with their traceback).\n");
}

const Subcommand* find_subcommand(const std::string& name) {
  for (const auto& s : subcommands())
    if (name == s.name) return &s;
  return nullptr;
}

std::string known_names() {
  std::vector<std::string> names;
  for (const auto& s : subcommands()) names.emplace_back(s.name);
  return text::join(names, ", ");
}

}  // namespace

int run_cli(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    print_main_help();
    return kExitUsage;
  }
  const std::string& first = args[0];
  if (first == "--help" || first == "-h") {
    print_main_help();
    return kExitOk;
  }
  if (first == "--version" || first == "-V") {
    std::printf("squawk %s\n", SQUAWK_VERSION);
    return kExitOk;
  }
  if (first == "help") {
    if (args.size() < 2) {
      print_main_help();
      return kExitOk;
    }
    const Subcommand* s = find_subcommand(args[1]);
    if (!s) {
      std::fprintf(stderr, "squawk help: no subcommand %s; known: %s\n", text::quoted(args[1]).c_str(),
                   known_names().c_str());
      return kExitUsage;
    }
    std::fputs(s->help, stdout);
    return kExitOk;
  }
  const Subcommand* s = find_subcommand(first);
  if (!s) {
    std::fprintf(stderr, "squawk: unknown subcommand %s; known: %s (see `squawk --help`)\n",
                 text::quoted(first).c_str(), known_names().c_str());
    return kExitUsage;
  }
  std::vector<std::string> rest(args.begin() + 1, args.end());
  // --openap DIR, accepted by every subcommand: OpenAP performance data for
  // every simulation of this run (as SQUAWK_OPENAP=DIR).
  for (size_t k = 0; k < rest.size(); ++k) {
    if (rest[k] != "--openap") continue;
    if (k + 1 >= rest.size()) {
      std::fprintf(stderr, "squawk %s: --openap expects the OpenAP data folder\n", s->name);
      return kExitUsage;
    }
    if (Status st = sim::set_default_openap(rest[k + 1]); !st.is_ok()) {
      std::fprintf(stderr, "squawk %s: --openap: %s\n", s->name, st.message().c_str());
      return kExitUsage;
    }
    rest.erase(rest.begin() + static_cast<long>(k), rest.begin() + static_cast<long>(k) + 2);
    break;
  }
  // --verbose, accepted by every subcommand: Lua errors with their traceback.
  // Not after `--`, nor after `run`'s script name (the script's own arguments).
  auto stop = std::find(rest.begin(), rest.end(), "--");
  if (std::string(s->name) == "run")
    stop = std::find_if(rest.begin(), stop, [](const std::string& a) { return a.rfind("--", 0) != 0; });
  if (auto v = std::find(rest.begin(), stop, "--verbose"); v != stop) {
    set_verbose(true);
    rest.erase(v);
  }
  if (!rest.empty() && (rest[0] == "--help" || rest[0] == "-h")) {
    std::fputs(s->help, stdout);
    return kExitOk;
  }
  try {
    return s->run(rest);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "squawk %s: internal error: %s\n", s->name, e.what());
    return kExitFail;
  }
}

}  // namespace squawk::app
