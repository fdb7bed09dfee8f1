#include "command/registry.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "core/edit_distance.h"
#include "core/text.h"

namespace squawk::command {

Registry::Registry() {
  add_traffic_commands(commands_);
  add_route_commands(commands_);
  add_sim_commands(commands_);
  add_asas_commands(commands_);
  add_perf_commands(commands_);
  add_shape_commands(commands_);
  for (auto& d : commands_) {
    auto sig = parse_signature(d.args);
    if (!sig) {
      // A malformed declaration is a bug in squawk; fail loudly at start-up.
      std::fprintf(stderr, "squawk: command %s: %s\n", d.name.c_str(), sig.status().message().c_str());
      std::abort();
    }
    d.signature = std::move(*sig);
  }
  std::sort(commands_.begin(), commands_.end(),
            [](const CommandDecl& a, const CommandDecl& b) { return a.name < b.name; });
  for (size_t i = 0; i < commands_.size(); ++i) {
    index_.emplace(commands_[i].name, i);
    for (const auto& a : commands_[i].aliases) index_.emplace(a, i);
  }
}

const Registry& Registry::instance() {
  static const Registry registry;
  return registry;
}

const CommandDecl* Registry::find(std::string_view name) const {
  auto it = index_.find(text::upper(name));
  return it == index_.end() ? nullptr : &commands_[it->second];
}

std::string Registry::closest(std::string_view name) const {
  const std::string want = text::upper(name);
  const size_t limit = want.size() >= 5 ? 2 : 1;
  const CommandDecl* best = nullptr;
  size_t best_d = limit + 1;
  for (const auto& d : commands_) {
    size_t dist = text::edit_distance(want, d.name);
    for (const auto& a : d.aliases) dist = std::min(dist, text::edit_distance(want, a));
    if (dist < best_d) {
      best_d = dist;
      best = &d;
    }
  }
  return best ? best->name : "";
}

std::string Registry::to_json() const {
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& d : commands_) {
    arr.push_back({{"name", d.name},
                   {"aliases", d.aliases},
                   {"args", d.args},
                   {"usage", d.usage},
                   {"help", d.help},
                   {"examples", d.examples}});
  }
  return arr.dump(2);
}

Result<std::string> Registry::help(std::string_view name) const {
  if (text::trim(name).empty()) {
    std::string out = "TrafScript commands (HELP NAME explains one):\n";
    for (const auto& d : commands_) out.append("  ").append(d.usage).append("\n");
    return out;
  }
  const CommandDecl* d = find(text::trim(name));
  if (!d) return Status::not_found("no command " + text::quoted(text::upper(text::trim(name))));
  std::string out = d->usage + "\n";
  if (!d->aliases.empty()) out.append("aliases: ").append(text::join(d->aliases, ", ")).append("\n");
  out.append(d->help).append("\n");
  for (const auto& e : d->examples) out.append("  e.g. ").append(e).append("\n");
  return out;
}

}  // namespace squawk::command
