// Vm: one sandboxed Lua 5.4 state with the squawk API.
//
// Sandbox (unless options.unsafe): base functions without dofile/loadfile,
// `load` restricted to text chunks, string, table, math, utf8, a safe print;
// `require` finds Lua files only under the shipped scripts/ folder, the running
// script's folder and options.require_dirs; io.open/io.lines/io.input read only
// inside readable folders (may_read) and write only inside options.out_dir;
// os.getenv sees only kEnvAllowList; os.execute, io.popen, package.loadlib and
// C modules raise an error that says how to allow them (--unsafe).
// math.random/randomseed draw from the engine Rng seeded with options.seed.
// Budget: options.max_instructions per call, counted across all coroutines
// (each coroutine is charged kHookEvery at creation, so short-lived ones are
// counted too), and C functions that do long work (simulation steps, episodes)
// charge their work through Vm::charge. A call is one entry from C++ into the
// VM (run_file, a reward function, a prompt renderer): Vm::Call resets the
// count at the outermost entry. options.max_seconds bounds a call's wall
// clock the same way (Watchdog); a call stuck that long inside one C function
// (a pathological string pattern) ends the process with exit code 124. Once the budget is spent every thread of the
// VM fails at its next instruction until the call ends.
// Memory: options.max_memory caps the VM's Lua heap (lua_setallocf); an
// allocation past it fails as Lua's "not enough memory", reported as the
// limit. A binding's C++ body may go kBindingSlack past it (so its own pushes
// never longjmp across C++ frames), then raises the limit's error on return.
// Finalizers (__gc) of script tables run in a fresh coroutine, where the
// count hook works (Lua turns hooks off in finalizers): they are charged to
// the budget like any code, and ~Vm runs the last ones under a fresh budget.
// Errors come back as Status with "file:line: message" and a traceback.
//
// Only files in engine/script/ include lua.h; other code sees lua_State as an
// opaque type.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/path_rules.h"
#include "core/rng.h"
#include "core/status.h"
#include "script/block_allocator.h"

struct lua_State;
struct lua_Debug;

namespace squawk::script {

class Watchdog;

// The environment variables a sandboxed os.getenv may see (no secrets).
inline constexpr const char* kEnvAllowList[] = {"SQUAWK_HOME", "SQUAWK_NAVDATA", "SQUAWK_LLM_URL",
                                                "SQUAWK_LLM_MODEL", "SQUAWK_LLM_API"};

struct VmOptions {
  uint64_t seed = 0;
  bool unsafe = false;
  std::string out_dir;  // the only folder files may be written to; "" = none
  long long max_instructions = 500'000'000;  // per call; 0 = no limit, < 0 refused
  double max_seconds = 0;                      // [s] wall clock per call; 0 = no limit
  long long max_memory = 1024LL << 20;         // [bytes] Lua heap of the VM; 0 = no limit
  std::vector<std::string> require_dirs;       // extra folders for `require`
  std::vector<std::string> read_dirs;          // extra folders scripts may read (--allow-read)
  std::string navdata_dir;                     // BlueSky navdata, "" = none
  long long max_conflict_pairs = 100'000;      // sim::CdSettings::max_pairs of every squawk.sim.new
};

// Counters of the assertion API (check, check_eq, check_near).
struct CheckCounts {
  long passed = 0;
  long failed = 0;
};

class Vm {
 public:
  explicit Vm(VmOptions options);
  ~Vm();
  Vm(const Vm&) = delete;
  Vm& operator=(const Vm&) = delete;

  // Runs a Lua file; `args` become the global `arg` (arg[0] = path).
  Status run_file(const std::string& path, const std::vector<std::string>& args = {});
  // Calls the function below the top `nargs` values with a traceback handler
  // and a fresh instruction budget (Call); `nresults` results stay on the
  // stack. On error the function and arguments are gone and the message,
  // with its traceback, comes back as kInvalidArgument.
  Status pcall(int nargs, int nresults);
  // `dir` joins the front of the require path (local modules win) and the
  // readable folders: what running a script in it does (run_file, LuaEnv).
  void add_script_folder(const std::string& dir);
  // Runs Lua source text under `chunkname` (shown in error messages).
  Status run_string(const std::string& code, const std::string& chunkname);
  // Runs a Lua file that returns a table (a prompt, template or config file)
  // and keeps that table in the Lua registry under `key`. Error when the file
  // fails or returns anything else.
  Status load_table(const std::string& path, const std::string& key);

  const VmOptions& options() const { return options_; }
  Rng& rng() { return rng_; }
  CheckCounts& checks() { return checks_; }
  lua_State* state() { return L_; }

  // The Vm that owns `L` (stored in the state's extra space).
  static Vm& of(lua_State* L);

  // The sandbox's path rules (paths::PathRules): reads inside the folder of
  // a script this Vm ran, the home's scripts/ prompts/ scenarios/ models/,
  // options.require_dirs, read_dirs, out_dir and navdata_dir; writes inside
  // out_dir. Everything with options.unsafe.
  const paths::PathRules& rules() const { return rules_; }
  bool may_read(const std::string& path) const { return rules_.check_read(path, "file").is_ok(); }

  // The message of the memory limit (options.max_memory).
  std::string memory_message() const;
  // Called by every binding around its C++ body (guarded<>): while one runs,
  // allocations may go kBindingSlack past the memory limit. leave_binding
  // returns false when the heap is past the limit.
  void enter_binding() { ++in_binding_; }
  bool leave_binding();

  // Whether a translation request's collector step is owed (script/translate_graph.h:
  // RequestCollection sets it, collect_after_reply clears it); a plain flag, so that setting it
  // never allocates in the Lua heap.
  bool collection_owed() const { return collection_owed_; }
  void set_collection_owed(bool owed) { collection_owed_ = owed; }

  // Charges `instructions` of work done in C to the current call's budget;
  // an error naming the limit when it is spent (the caller raises it).
  Status charge(long long instructions);

  // One entry from C++ into the VM: the outermost one starts a fresh budget.
  class Call {
   public:
    explicit Call(Vm& vm);
    ~Call();
    Call(const Call&) = delete;
    Call& operator=(const Call&) = delete;

   private:
    Vm& vm_;
    int in_binding_;  // restored at the end: a binding left by a longjmp
  };

  static constexpr long long kBindingSlack = 64LL << 20;  // [bytes]

 private:
  void open_sandbox();

  VmOptions options_;
  Rng rng_;
  CheckCounts checks_;
  long long instructions_ = 0;  // spent in the current call
  int call_depth_ = 0;
  std::unique_ptr<Watchdog> watchdog_;  // the current call's, when max_seconds > 0
  paths::PathRules rules_;
  bool stopped_ = false;  // the budget of the current call is spent
  size_t heap_ = 0;       // [bytes] Lua heap in use
  int in_binding_ = 0;    // binding bodies running
  bool memory_refused_ = false;  // an allocation failed at the limit
  bool collection_owed_ = false;  // a translation request's collector step is owed
  BlockAllocator blocks_;        // the Lua heap's blocks; outlives L_ (declared before it)
  friend void* vm_alloc(void* ud, void* ptr, size_t osize, size_t nsize);
  lua_State* L_ = nullptr;
  friend void count_hook(lua_State* L, ::lua_Debug* ar);
  friend int counted_coroutine(lua_State* L);
};

}  // namespace squawk::script
