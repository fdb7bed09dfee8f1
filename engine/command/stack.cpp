#include "command/stack.h"

#include <cmath>
#include <filesystem>

#include "command/bluesky_only.h"
#include "command/line.h"
#include "command/registry.h"
#include "command/scn.h"
#include "core/geo.h"
#include "core/paths.h"
#include "core/text.h"
#include "core/units.h"
#include "sim/byte_image.h"

namespace fs = std::filesystem;

namespace squawk::command {

namespace {

constexpr int kMaxIncludeDepth = 16;      // nested IC / PCALL files
constexpr long kMaxPerInstant = 100'000;  // queued commands run at one sim time
constexpr size_t kMaxQueued = 1'000'000;  // commands waiting in the queue
constexpr int kMaxNested = 8;             // NEAR inside NEAR

// A failure's grouping key: the message with quoted values and a leading
// aircraft id ("KL1: ...", as the simulation words it) blanked, so failures
// that differ only in names count as one reason.
std::string blank_names(std::string_view msg) {
  if (auto colon = msg.find(": "); colon != std::string_view::npos && colon > 0 &&
                                   msg.substr(0, colon).find(' ') == std::string_view::npos &&
                                   msg.substr(0, colon) != "argument") {
    return "<acid>: " + blank_names(msg.substr(colon + 2));
  }
  std::string out;
  bool in_quote = false;
  for (char c : msg) {
    if (c == '\'') {
      out.push_back(c);
      if (!in_quote) out.append("...");
      in_quote = !in_quote;
      continue;
    }
    if (!in_quote) out.push_back(c);
  }
  if (auto u = out.find(" (usage:"); u != std::string::npos) out.resize(u);
  return out;
}

// The resolved command of one text: its declaration and argument text.
struct Resolved {
  const CommandDecl* decl = nullptr;
  std::string name;     // as typed, upper case (the unknown name when decl is null)
  std::string argtext;  // arguments, with a leading acid moved in place
  bool acid_unknown = false;  // "X CMD ..." where X is no aircraft but CMD is a command
};

Resolved resolve(std::string_view text, const sim::Traffic& traf) {
  const Registry& reg = Registry::instance();
  ArgReader r(text);
  Resolved out;
  out.name = text::upper(r.next());
  out.decl = reg.find(out.name);
  out.argtext = std::string(r.rest());
  if (out.decl) return out;
  ArgReader look = r;
  const std::string second = text::upper(look.next());
  if (traf.index_of(out.name) >= 0) {
    const std::string acid = out.name;
    out.name = second.empty() ? "POS" : second;
    out.decl = reg.find(out.name);
    out.argtext = acid;
    if (!look.rest().empty()) out.argtext.append(" ").append(look.rest());
    return out;
  }
  // "KL999 ALT FL100": a command whose first argument is an aircraft, after
  // something that is no aircraft. Anything else is an unknown command.
  const CommandDecl* d = second.empty() ? nullptr : reg.find(second);
  if (d && !d->signature.params.empty() && d->signature.params[0].alternatives.front() == ArgType::kAcid) {
    out.acid_unknown = true;
    out.decl = d;
  }
  return out;
}

// "NAME: reason" for a failed command `typed` whose message starts with it.
std::string reason_key(std::string_view typed, const std::string& msg, const sim::Traffic& traf) {
  const Resolved rc = resolve(typed, traf);
  std::string_view rest = msg;
  if (rest.substr(0, typed.size()) == typed) rest.remove_prefix(typed.size());
  if (rest.substr(0, 2) == ": ") rest.remove_prefix(2);
  return (rc.decl ? rc.decl->name : rc.name) + ": " + blank_names(rest);
}

std::string usage_suffix(const CommandDecl& d) { return " (usage: " + d.usage + ")"; }

// Parses the arguments of a resolved command; `*` only where the command
// takes every aircraft.
Result<ParsedArgs> parse_call(const Resolved& rc, const std::string& typed,
                              const ParseContext& ctx) {
  auto args = parse_args(rc.decl->signature, rc.argtext, ctx);
  if (!args)
    return Status::error(args.status().code(), typed + ": " + args.status().message() + usage_suffix(*rc.decl));
  if (!rc.decl->all_aircraft)
    for (size_t k = 0; k < args->values.size(); ++k)
      if (args->values[k].type == ArgType::kAcid && args->values[k].acids.size() > 1)
        return Status::invalid(typed + ": argument " + std::to_string(k + 1) +
                               ": '*' (every aircraft) is not accepted here; name one aircraft" +
                               usage_suffix(*rc.decl));
  return args;
}

}  // namespace

const ArgValue& Call::operator[](size_t i) const {
  static const ArgValue kAbsent;
  return i < args.size() ? args[i] : kAbsent;
}

Stack::Stack(uint64_t seed) : sim_(seed), seed_(seed) {}

ParseContext Stack::parse_context() const {
  ParseContext ctx;
  ctx.traffic = &sim_.traffic();
  ctx.navdb = navdb_.get();
  ctx.user_wpts = &user_wpts_;
  ctx.ref = ref_;
  return ctx;
}

Result<std::string> Stack::run_command(std::string_view text, bool from_queue, bool* skipped) {
  const std::string typed(text::trim(text));
  Resolved rc = resolve(typed, sim_.traffic());
  if (!rc.decl) {
    if (from_queue && bluesky_only(rc.name)) {
      ++tally_.skipped[rc.name];
      *skipped = true;
      return std::string();
    }
    const std::string near = Registry::instance().closest(rc.name);
    return Status::not_found(typed + ": unknown command or aircraft " + text::quoted(rc.name) +
                             (near.empty() ? "" : " - did you mean " + near + "?") + " (`HELP` lists the commands)");
  }
  if (rc.acid_unknown)
    return Status::not_found(typed + ": no aircraft " + text::quoted(rc.name) + usage_suffix(*rc.decl));
  SQUAWK_ASSIGN_OR_RETURN(auto parsed, parse_call(rc, typed, parse_context()));
  // The parse's reference stands before the handler runs (RESET and IC clear
  // it, NEAR sets it for its command) and is taken back when the command fails.
  const GeoPoint ref_before = ref_;
  ref_ = parsed.ref;
  Call call{*this, rc.decl->name, parsed.values};
  auto out = rc.decl->handler(call);
  if (!out) {
    ref_ = ref_before;
    return Status::error(out.status().code(), typed + ": " + out.status().message());
  }
  return out;
}

Result<std::string> Stack::run_nested(std::string_view command) {
  if (nested_depth_ >= kMaxNested)
    return Status::invalid("more than " + std::to_string(kMaxNested) +
                           " commands nested in one another");
  bool skipped = false;
  ++nested_depth_;
  auto out = run_command(command, !where_.empty(), &skipped);
  --nested_depth_;
  return out;
}

Result<std::string> Stack::exec(std::string_view line) {
  std::string joined;
  for (const auto& cmd : split_commands(line)) {
    bool skipped = false;
    auto r = run_command(cmd, false, &skipped);
    if (!r) {
      ++tally_.failed[reason_key(text::trim(cmd), r.status().message(), sim_.traffic())];
      return r.status();
    }
    ++tally_.executed;
    if (!r->empty()) {
      if (!joined.empty()) joined.push_back('\n');
      joined.append(*r);
    }
  }
  return joined;
}

Status Stack::check(std::string_view line) const {
  ParseContext ctx = parse_context();
  for (const auto& cmd : split_commands(line)) {
    const std::string typed(text::trim(cmd));
    Resolved rc = resolve(typed, sim_.traffic());
    if (!rc.decl)
      return Status::not_found(typed + ": unknown command or aircraft " + text::quoted(rc.name));
    if (rc.acid_unknown)
      return Status::not_found(typed + ": no aircraft " + text::quoted(rc.name) + usage_suffix(*rc.decl));
    SQUAWK_ASSIGN_OR_RETURN(const ParsedArgs parsed, parse_call(rc, typed, ctx));
    ctx.ref = parsed.ref;  // each command starts from the reference the one before left
  }
  return Status::ok();
}

void Stack::run_queued(const Queued& q) {
  const std::string outer = where_;  // a PCALL runs queued lines inside another
  where_ = q.where;
  for (const auto& cmd : split_commands(q.line)) {
    bool skipped = false;
    auto r = run_command(cmd, true, &skipped);
    if (!r) {
      ++tally_.failed[reason_key(text::trim(cmd), r.status().message(), sim_.traffic())];
      std::string msg = "t=" + text::fmt_double(sim_.simt(), 2) + " s: " + (q.where.empty() ? "" : q.where + ": ") +
                        r.status().message();
      if (tally_.first_failures.size() < Tally::kMaxKept) tally_.first_failures.push_back(msg);
      output_.push_back(std::move(msg));
      continue;
    }
    if (!skipped) ++tally_.executed;
    if (!r->empty()) output_.push_back(*r);
  }
  where_ = outer;
}

void Stack::process_due() {
  std::vector<Queued> fired;
  fired.swap(fired_);
  for (const auto& q : fired) run_queued(q);
  long ran = 0;
  while (!queue_.empty() && queue_.begin()->first.first <= sim_.simt()) {
    if (++ran > kMaxPerInstant) {  // a SCHEDULE / PCALL loop at this instant
      size_t dropped = 0;
      while (!queue_.empty() && queue_.begin()->first.first <= sim_.simt()) {
        queue_.erase(queue_.begin());
        ++dropped;
      }
      record_failure("more than " + std::to_string(kMaxPerInstant) + " queued commands at one time (" +
                     std::to_string(dropped) + " dropped; a SCHEDULE or PCALL loop?)");
      return;
    }
    if (ran % 64 == 0 && past_deadline()) return;
    Queued q = std::move(queue_.begin()->second);
    queue_.erase(queue_.begin());
    run_queued(q);
  }
}

void Stack::record_failure(const std::string& what) {
  if (++tally_.failed[what.substr(0, what.find(" ("))] > 10) return;  // counted, not repeated
  std::string msg = "t=" + text::fmt_double(sim_.simt(), 2) + " s: " + (where_.empty() ? "" : where_ + ": ") + what;
  if (tally_.first_failures.size() < Tally::kMaxKept) tally_.first_failures.push_back(msg);
  output_.push_back(std::move(msg));
}

void Stack::test_conditions() {
  if (conditions_.empty()) return;
  const sim::Traffic& t = sim_.traffic();
  std::vector<Condition> keep;
  keep.reserve(conditions_.size());
  for (auto& c : conditions_) {
    const int i = t.index_of(c.acid);
    if (i < 0) continue;  // the aircraft is gone: drop its conditions
    double actual = 0.0;
    switch (c.kind) {
      case Condition::Kind::kAlt: actual = t.alt[i]; break;
      case Condition::Kind::kSpd: actual = t.cas[i]; break;
      case Condition::Kind::kDist:
        actual = units::m_to_nm(geo::gc_distance_m(t.lat[i], t.lon[i], c.pos.lat, c.pos.lon));
        break;
    }
    const double diff = c.target - actual;
    if (diff * c.last_diff <= 0.0) {
      fired_.push_back({c.command, c.where});
      continue;
    }
    c.last_diff = diff;
    keep.push_back(std::move(c));
  }
  conditions_.swap(keep);
}

void Stack::queue_passages() {
  for (const sim::Simulation::Passage& p : sim_.passages())
    for (const std::string& line : p.commands) fired_.push_back({line, p.acid + " AT " + p.wpt});
}

void Stack::step() {
  process_due();
  sim_.step();
  queue_passages();
  test_conditions();
}

Status Stack::run_until(double t_end) {
  if (!std::isfinite(t_end)) return Status::invalid("run until: time must be finite");
  while (true) {
    process_due();
    if (past_deadline())
      return Status::timeout("the wall-clock deadline passed at t = " + text::fmt_double(sim_.simt(), 2) + " s");
    if (sim_.simt() + 0.5 * sim_.dt() > t_end) break;
    const double before = sim_.simt();
    sim_.step();
    queue_passages();
    test_conditions();
    if (!(sim_.simt() > before))
      return Status::invalid("run until: the time step " + text::fmt_double(sim_.dt(), 9) +
                             " s no longer advances the clock at t = " + text::fmt_double(before, 2) + " s");
  }
  return Status::ok();
}

void Stack::schedule(double t, std::string line) {
  if (queue_.size() >= kMaxQueued) {
    record_failure("the command queue is full (" + std::to_string(kMaxQueued) + " commands; a self-scheduling loop?): " +
                   text::quoted(line) + " dropped");
    return;
  }
  queue_.emplace(std::make_pair(t, next_seq_++), Queued{std::move(line), where_});
}

std::optional<double> Stack::last_queued_time() const {
  if (queue_.empty()) return std::nullopt;
  return queue_.rbegin()->first.first;
}

namespace {

// `name` in `dir`: as given, else with a .scn suffix of any case (BlueSky
// forces .scn), else any file whose name matches case-insensitively.
std::optional<std::string> find_in(const fs::path& dir, const fs::path& name) {
  std::error_code ec;
  const fs::path p = dir / name;
  if (fs::is_regular_file(p, ec)) return p.string();
  fs::path stem = p;
  if (text::iequals(stem.extension().string(), ".scn")) stem.replace_extension();
  const std::string want = text::upper(stem.filename().string() + ".scn");
  const fs::path folder = stem.parent_path();
  if (!fs::is_directory(folder, ec)) return std::nullopt;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (e.is_regular_file(ec) && text::upper(e.path().filename().string()) == want) return e.path().string();
  return std::nullopt;
}

}  // namespace

Result<std::string> Stack::find_scenario(const std::string& name) const {
  if (text::trim(name).empty()) return Status::invalid("scenario file name is empty");
  const fs::path p(std::string(text::trim(name)));
  if (p.is_absolute()) {
    if (auto f = find_in(p.root_path(), p.relative_path())) return *f;
  } else {
    // The base folder, then its parents: scenarios in sub-folders of a
    // scenario tree name their includes relative to the tree's root.
    std::error_code ec;
    for (fs::path dir = fs::absolute(base_dir_, ec); !dir.empty(); dir = dir.parent_path()) {
      if (auto f = find_in(dir, p)) return *f;
      if (dir == dir.parent_path()) break;
    }
  }
  return Status::not_found("no scenario file " + text::quoted(name) + " (looked in " + text::quoted(base_dir_) +
                           " and its parent folders)");
}

Status Stack::check_read(const std::string& path, std::string_view what) const {
  return rules_ ? rules_->check_read(path, what) : Status::ok();
}

Status Stack::check_read_folder(const std::string& dir, std::string_view what) const {
  return rules_ ? rules_->check_read_folder(dir, what) : Status::ok();
}

Result<std::pair<std::string, ScnFile>> Stack::read_included(const std::string& path) const {
  if (include_depth_ >= kMaxIncludeDepth)
    return Status::invalid("scenario " + text::quoted(path) + ": more than " +
                           std::to_string(kMaxIncludeDepth) + " nested IC/PCALLs");
  if (!path.empty() && path.front() == '/') SQUAWK_RETURN_IF_ERROR(check_read(path, "scenario"));
  SQUAWK_ASSIGN_OR_RETURN(std::string file, find_scenario(path));
  SQUAWK_RETURN_IF_ERROR(check_read(file, "scenario"));
  SQUAWK_ASSIGN_OR_RETURN(ScnFile scn, read_scn(file));
  return std::make_pair(std::move(file), std::move(scn));
}

Status Stack::merge_scenario(const std::string& path, const std::vector<std::string>& args, bool relative) {
  SQUAWK_ASSIGN_OR_RETURN(auto read, read_included(path));
  merge_entries(read.first, std::move(read.second), args, relative);
  return Status::ok();
}

void Stack::merge_entries(const std::string& file, ScnFile scn, const std::vector<std::string>& args,
                          bool relative) {
  const double offset = relative ? sim_.simt() : 0.0;
  const std::string outer = where_;  // a PCALL's own line, restored after its entries are queued
  std::vector<Queued> now;  // due already: run at once, in file order (BlueSky's merge)
  for (auto& e : scn.entries) {
    std::string line = std::move(e.command);
    for (size_t k = 0; k < args.size(); ++k) {
      const std::string key = "%" + std::to_string(k);
      for (size_t pos = line.find(key); pos != std::string::npos; pos = line.find(key, pos + args[k].size()))
        line.replace(pos, key.size(), args[k]);
    }
    const std::string at = file + ":" + std::to_string(e.line);
    if (e.time + offset <= sim_.simt()) {
      now.push_back({std::move(line), at});
    } else {
      where_ = at;
      schedule(e.time + offset, std::move(line));
    }
  }
  where_ = outer;
  for (const auto& bad : scn.rejected) {
    ++tally_.failed["(scenario file): unreadable timestamp, line skipped"];
    std::string msg = file + ":" + std::to_string(bad.line) + ": unreadable timestamp, line skipped";
    if (tally_.first_failures.size() < Tally::kMaxKept) tally_.first_failures.push_back(msg);
    output_.push_back(std::move(msg));
  }
  ++include_depth_;
  for (const auto& q : now) run_queued(q);
  --include_depth_;
  where_ = outer;
}

Status Stack::load_scenario(const std::string& path) {
  SQUAWK_ASSIGN_OR_RETURN(auto read, read_included(path));
  reset();
  merge_entries(read.first, std::move(read.second), {}, false);
  return Status::ok();
}

void Stack::reset() {
  sim_.reset(seed_);
  queue_.clear();
  next_seq_ = 0;
  conditions_.clear();
  fired_.clear();
  user_wpts_.clear();
  ref_ = GeoPoint{};
  noise_ = false;
  trails_ = Trails();
}

void Stack::set_seed(uint64_t seed) {
  seed_ = seed;
  sim_.rng().reseed(seed);
}

Status Stack::define_waypoint(const std::string& name, GeoPoint pos) {
  if (name.empty()) return Status::invalid("waypoint name is empty");
  user_wpts_[text::upper(name)] = pos;
  return Status::ok();
}

Status Stack::delete_user_waypoint(const std::string& name) {
  if (user_wpts_.erase(text::upper(name)) == 0)
    return Status::not_found("no user waypoint " + text::quoted(name));
  return Status::ok();
}

std::vector<std::string> Stack::take_output() {
  std::vector<std::string> out;
  out.swap(output_);
  return out;
}

std::string Stack::snapshot() const {
  namespace b = sim::bytes;
  std::string out = sim_.snapshot();
  b::put<int64_t>(out, static_cast<int64_t>(queue_.size()));
  for (const auto& [key, q] : queue_) {
    b::put<double>(out, key.first);
    b::put<uint64_t>(out, key.second);
    b::put_str(out, q.line);
    b::put_str(out, q.where);
  }
  b::put<uint64_t>(out, next_seq_);
  b::put<int64_t>(out, static_cast<int64_t>(conditions_.size()));
  for (const auto& c : conditions_) {
    b::put_str(out, c.acid);
    b::put<int32_t>(out, static_cast<int32_t>(c.kind));
    b::put<double>(out, c.target);
    b::put<double>(out, c.last_diff);
    b::put<double>(out, c.pos.lat);
    b::put<double>(out, c.pos.lon);
    b::put_str(out, c.command);
    b::put_str(out, c.where);
  }
  b::put<int64_t>(out, static_cast<int64_t>(fired_.size()));
  for (const auto& f : fired_) {
    b::put_str(out, f.line);
    b::put_str(out, f.where);
  }
  b::put<int64_t>(out, static_cast<int64_t>(user_wpts_.size()));
  for (const auto& [name, p] : user_wpts_) {
    b::put_str(out, name);
    b::put<double>(out, p.lat);
    b::put<double>(out, p.lon);
  }
  b::put<double>(out, ref_.lat);
  b::put<double>(out, ref_.lon);
  b::put<uint64_t>(out, seed_);
  b::put<double>(out, sim_.dtmult());
  b::put<uint8_t>(out, noise_ ? 1 : 0);
  b::put<uint8_t>(out, trails_.on ? 1 : 0);
  b::put<double>(out, trails_.dt);
  b::put<int64_t>(out, static_cast<int64_t>(trails_.colour.size()));
  for (const auto& [acid, colour] : trails_.colour) {
    b::put_str(out, acid);
    b::put_str(out, colour);
  }
  b::put_str(out, base_dir_);
  return out;
}

}  // namespace squawk::command
