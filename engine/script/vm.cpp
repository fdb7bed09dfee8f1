#include "script/vm.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "core/paths.h"
#include "script/bindings.h"
#include "script/lua_util.h"
#include "script/watchdog.h"

namespace squawk::script {

namespace {

constexpr int kHookEvery = 10000;  // instructions between hook calls

// print: tostring of each argument, tab-separated, newline, to stdout.
int safe_print(lua_State* L) {
  const int n = lua_gettop(L);
  for (int i = 1; i <= n; ++i) {
    size_t len = 0;
    const char* s = luaL_tolstring(L, i, &len);
    if (i > 1) std::fputc('\t', stdout);
    std::fwrite(s, 1, len, stdout);
    lua_pop(L, 1);
  }
  std::fputc('\n', stdout);
  std::fflush(stdout);
  return 0;
}

// A stand-in for a function the sandbox withholds; upvalue 1 is its name.
int forbidden(lua_State* L) {
  const char* name = lua_tostring(L, lua_upvalueindex(1));
  return luaL_error(L,
                    "%s is not allowed in the sandbox; run squawk with --unsafe to allow it "
                    "(only for scripts you trust)",
                    name);
}

void set_forbidden(lua_State* L, int table, const char* lib, const char* fn) {
  table = lua_absindex(L, table);
  lua_pushfstring(L, "%s.%s", lib, fn);
  lua_pushcclosure(L, forbidden, 1);
  lua_setfield(L, table, fn);
}

// load(chunk, name, mode, env) with mode forced to text.
int text_only_load(lua_State* L) {
  lua_settop(L, 4);
  lua_pushstring(L, "t");
  lua_replace(L, 3);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, 4, LUA_MULTRET);
  return lua_gettop(L);
}

// Raises the sandbox's error unless `path` may be opened with `mode`.
void check_file_access(lua_State* L, const char* path, const char* mode) {
  char msg[1024] = "";  // no C++ object may live across luaL_error's longjmp
  {
    const paths::PathRules& rules = Vm::of(L).rules();
    const Status st = std::strpbrk(mode, "wa+") != nullptr ? rules.check_write(path, "io.open")
                                                           : rules.check_read(path, "io.open");
    if (!st.is_ok()) std::snprintf(msg, sizeof msg, "%s", st.message().c_str());
  }
  if (msg[0]) luaL_error(L, "%s", msg);
}

// The check again on what was opened: each file handle among the values
// from `first` to the top must be the file the check allowed (a link swapped
// between the check by name and the open leads elsewhere); such a handle is
// closed and the sandbox's error raised.
void check_opened(lua_State* L, int first, const char* path, bool write) {
  char msg[1024] = "";  // no C++ object may live across luaL_error's longjmp
  for (int i = first; i <= lua_gettop(L); ++i) {
    auto* stream = static_cast<luaL_Stream*>(luaL_testudata(L, i, LUA_FILEHANDLE));
    if (!stream || !stream->closef || !stream->f) continue;
    {
      const paths::PathRules& rules = Vm::of(L).rules();
      const int fd = fileno(stream->f);
      const Status st = write ? rules.check_write_fd(fd, path, "io.open") : rules.check_read_fd(fd, path, "io.open");
      if (!st.is_ok()) std::snprintf(msg, sizeof msg, "%s", st.message().c_str());
    }
    if (msg[0]) {
      std::fclose(stream->f);
      stream->closef = nullptr;  // the io library's mark of a closed handle
      luaL_error(L, "%s", msg);
    }
  }
}

// io.open(path, mode) through check_file_access, then check_opened;
// upvalue 1 is the original.
int checked_open(lua_State* L) {
  const char* path = luaL_checkstring(L, 1);
  const char* mode = luaL_optstring(L, 2, "r");
  check_file_access(L, path, mode);
  lua_settop(L, 2);
  const int base = lua_gettop(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushvalue(L, 1);
  lua_pushstring(L, mode);
  lua_call(L, 2, LUA_MULTRET);
  check_opened(L, base + 1, path, std::strpbrk(mode, "wa+") != nullptr);
  return lua_gettop(L) - base;
}

// io.lines(path, ...) and io.input(path): reads of a named file are checked
// (before and after opening); upvalue 1 is the original.
int checked_read(lua_State* L) {
  const char* path = lua_type(L, 1) == LUA_TSTRING ? lua_tostring(L, 1) : nullptr;
  if (path) check_file_access(L, path, "r");
  const int n = lua_gettop(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  for (int i = 1; i <= n; ++i) lua_pushvalue(L, i);
  lua_call(L, n, LUA_MULTRET);
  if (path) check_opened(L, n + 1, path, false);
  return lua_gettop(L) - n;
}

// __gc of a script table, installed by guarded_setmetatable; upvalue 1 is the
// script's finalizer. Lua runs finalizers with hooks off, so the finalizer
// runs in a fresh coroutine, which inherits the count hook: a loop in it is
// charged to the budget and stopped. Its errors end it (as Lua ignores a
// finalizer's errors).
int gc_trampoline(lua_State* L) {
  lua_State* T = lua_newthread(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushvalue(L, 1);
  lua_xmove(L, T, 2);
  int nres = 0;
  lua_resume(T, L, 1, &nres);
  return 0;
}

// setmetatable(t, mt); upvalue 1 is the original. When mt holds __gc, t gets
// a copy of mt whose __gc is gc_trampoline around mt's finalizer and whose
// __metatable is mt (getmetatable(t) still returns mt). The copies are kept
// in the registry's weak set squawk.gc_shadows so t's metatable may be set again.
int guarded_setmetatable(lua_State* L) {
  lua_settop(L, 2);
  bool has_gc = false;
  if (lua_type(L, 2) == LUA_TTABLE) {
    lua_pushliteral(L, "__gc");
    has_gc = lua_rawget(L, 2) != LUA_TNIL;
    lua_pop(L, 1);
  }
  lua_getfield(L, LUA_REGISTRYINDEX, "squawk.gc_shadows");
  const int shadows = lua_gettop(L);
  bool shadowed = false;  // t's current metatable is one of our copies
  if (lua_type(L, 1) == LUA_TTABLE && lua_getmetatable(L, 1)) {
    shadowed = lua_rawget(L, shadows) != LUA_TNIL;
    lua_pop(L, 1);
  }
  if (!has_gc && !shadowed) {
    lua_settop(L, 2);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, 2, 1);
    return 1;
  }
  luaL_checktype(L, 1, LUA_TTABLE);
  if (!has_gc) {  // replacing one of our copies: the original's checks, then set
    luaL_argexpected(L, lua_isnoneornil(L, 2) || lua_istable(L, 2), 2, "nil or table");
    lua_settop(L, 2);
    lua_setmetatable(L, 1);
    return 1;
  }
  lua_newtable(L);  // the copy
  const int copy = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, 2)) {
    lua_pushvalue(L, -2);
    lua_insert(L, -2);
    lua_rawset(L, copy);
  }
  lua_pushliteral(L, "__gc");
  lua_pushliteral(L, "__gc");
  if (lua_rawget(L, 2) == LUA_TFUNCTION) {
    lua_pushcclosure(L, gc_trampoline, 1);
  } else {
    lua_pop(L, 1);
    lua_pushboolean(L, 0);  // not a function: Lua would call nothing either
  }
  lua_rawset(L, copy);
  lua_pushliteral(L, "__metatable");
  if (lua_rawget(L, copy) == LUA_TNIL) {
    lua_pop(L, 1);
    lua_pushliteral(L, "__metatable");
    lua_pushvalue(L, 2);
    lua_rawset(L, copy);
  } else {
    lua_pop(L, 1);
  }
  if (!shadowed && luaL_getmetafield(L, 1, "__metatable") != LUA_TNIL)
    return luaL_error(L, "cannot change a protected metatable");
  lua_pushvalue(L, copy);
  lua_pushboolean(L, 1);
  lua_rawset(L, shadows);
  lua_pushvalue(L, copy);
  lua_setmetatable(L, 1);
  lua_settop(L, 1);
  return 1;
}

// string.find/match/gmatch/gsub; upvalue 1 is the original. Charges
// (#s + 1) * (#pattern + 1) / 16 instructions first: a scan costs about
// #pattern steps per subject byte, 16 of them per VM instruction. Backtracking
// beyond that is bounded by --max-seconds (Watchdog).
int charged_pattern(lua_State* L) {
  const auto cost = static_cast<long long>((lua_rawlen(L, 1) + 1) * (lua_rawlen(L, 2) + 1) / 16);
  char msg[256] = "";  // no C++ object may live across luaL_error's longjmp
  if (const Status st = Vm::of(L).charge(cost); !st.is_ok())
    std::snprintf(msg, sizeof msg, "%s", st.message().c_str());
  if (msg[0]) return luaL_error(L, "%s", msg);
  const int n = lua_gettop(L);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, n, LUA_MULTRET);
  return lua_gettop(L);
}

// os.getenv(name): only the names in kEnvAllowList; others are nil.
int checked_getenv(lua_State* L) {
  const char* name = luaL_checkstring(L, 1);
  for (const char* allowed : kEnvAllowList) {
    if (std::strcmp(name, allowed) == 0) {
      const char* v = std::getenv(name);
      if (v) lua_pushstring(L, v);
      else lua_pushnil(L);
      return 1;
    }
  }
  lua_pushnil(L);
  return 1;
}

// lua_load's reader over an open file; a first line starting with '#' is
// skipped (as luaL_loadfilex does).
struct FileReader {
  FILE* f;
  bool first = true;
  char buf[4096] = {};
};

const char* read_file_chunk(lua_State*, void* data, size_t* size) {
  auto* r = static_cast<FileReader*>(data);
  if (r->first) {
    r->first = false;
    const int c = std::getc(r->f);
    if (c == '#') {
      int d = 0;
      while ((d = std::getc(r->f)) != EOF && d != '\n') {
      }
      r->buf[0] = '\n';  // keeps the line numbers
      *size = 1;
      return r->buf;
    }
    if (c != EOF) std::ungetc(c, r->f);
  }
  *size = std::fread(r->buf, 1, sizeof r->buf, r->f);
  return *size > 0 ? r->buf : nullptr;
}

// Loads the open file `f` as a text chunk named "@path"; lua_load's status,
// with the function or the message pushed.
int load_open_file(lua_State* L, FILE* f, const char* path) {
  FileReader reader{f};
  lua_pushfstring(L, "@%s", path);
  const int rc = lua_load(L, read_file_chunk, &reader, lua_tostring(L, -1), "t");
  lua_remove(L, -2);
  if (rc == LUA_OK && std::ferror(f)) {
    lua_pop(L, 1);
    lua_pushfstring(L, "cannot read %s", path);
    return LUA_ERRFILE;
  }
  return rc;
}

// package.searchers entry: Lua files under the allowed folders only.
int lua_file_searcher(lua_State* L) {
  const char* name = luaL_checkstring(L, 1);
  char rel[512];  // a C array: no C++ object may live across luaL_error's longjmp
  std::snprintf(rel, sizeof rel, "%s", name);
  for (char* c = rel; *c; ++c)
    if (*c == '.') *c = '/';
  lua_getfield(L, LUA_REGISTRYINDEX, "squawk.require_dirs");
  const int dirs = lua_gettop(L);
  const lua_Integer n = luaL_len(L, dirs);
  luaL_Buffer tried;
  luaL_buffinit(L, &tried);
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_geti(L, dirs, i);
    const char* dir = lua_tostring(L, -1);
    for (const char* pattern : {"%s/%s.lua", "%s/%s/init.lua"}) {
      lua_pushfstring(L, pattern, dir, rel);
      const char* file = lua_tostring(L, -1);
      if (FILE* f = std::fopen(file, "r")) {
        // Checked by name, then as opened, and loaded from this open file:
        // a link swapped in between cannot lead out.
        char refused[1024] = "";  // no C++ object may live across luaL_error's longjmp
        {
          const paths::PathRules& rules = Vm::of(L).rules();
          Status st = rules.check_read(file, "require");
          if (st.is_ok()) st = rules.check_read_fd(fileno(f), file, "require");
          if (!st.is_ok()) std::snprintf(refused, sizeof refused, "%s", st.message().c_str());
        }
        if (refused[0]) {
          std::fclose(f);
          return luaL_error(L, "module '%s': %s", name, refused);
        }
        const int rc = load_open_file(L, f, file);
        std::fclose(f);
        if (rc != LUA_OK)
          return luaL_error(L, "error loading module '%s' from '%s':\n\t%s", name, file,
                            lua_tostring(L, -1));
        lua_pushvalue(L, -2);  // file name as second loader argument
        return 2;
      }
      lua_pop(L, 1);
    }
    lua_pop(L, 1);
  }
  lua_pushfstring(L, "no file '%s.lua' in the allowed folders (scripts/, the script's folder)",
                  rel);
  return 1;
}

}  // namespace

void* vm_alloc(void* ud, void* ptr, size_t osize, size_t nsize) {
  Vm& vm = *static_cast<Vm*>(ud);
  const size_t old = ptr ? osize : 0;  // without ptr, osize names the object's type
  if (nsize == 0) {
    vm.blocks_.release(ptr, old);
    vm.heap_ -= old;
    return nullptr;
  }
  const long long limit = vm.options_.max_memory;
  if (limit > 0 && nsize > old) {
    const auto cap = static_cast<size_t>(limit + (vm.in_binding_ > 0 ? Vm::kBindingSlack : 0));
    if (vm.heap_ - old + nsize > cap) {
      vm.memory_refused_ = true;
      return nullptr;
    }
  }
  void* p = vm.blocks_.resize(ptr, old, nsize);
  if (p) vm.heap_ = vm.heap_ - old + nsize;
  return p;
}

std::string Vm::memory_message() const {
  return "stopped: the script's Lua memory reached " + std::to_string(options_.max_memory >> 20) +
         " MiB, the limit per VM; raise it with --max-memory MB, or 0 for no limit";
}

bool Vm::leave_binding() {
  --in_binding_;
  return options_.max_memory <= 0 || heap_ <= static_cast<size_t>(options_.max_memory);
}

namespace {

std::string limit_message(long long limit) {
  return "stopped: the script ran " + std::to_string(limit) +
         " Lua instructions, the limit for one call (runaway loop?); raise it with "
         "--max-instructions N, or 0 for no limit";
}

}  // namespace

void count_hook(lua_State* L, lua_Debug* ar) {
  Vm& vm = Vm::of(L);
  if (lua_gethookcount(L) == 1 && !vm.stopped_ && !(vm.watchdog_ && vm.watchdog_->expired())) {  // a thread left failing by an earlier call
    lua_sethook(L, count_hook, LUA_MASKCOUNT, kHookEvery);
    return;
  }
  if (vm.watchdog_ && vm.watchdog_->expired()) {
    lua_sethook(L, count_hook, LUA_MASKCOUNT, 1);  // keep failing if a pcall catches it
    lua_getinfo(L, "Sl", ar);
    luaL_error(L, "%s:%d: stopped: the call ran longer than %f s of wall-clock time; raise it with "
               "--max-seconds S, or 0 for no limit", ar->short_src, ar->currentline,
               vm.options_.max_seconds);
  }
  vm.instructions_ += kHookEvery;
  const long long limit = vm.options_.max_instructions;
  if (limit > 0 && (vm.stopped_ || vm.instructions_ >= limit)) {
    vm.stopped_ = true;
    lua_sethook(L, count_hook, LUA_MASKCOUNT, 1);  // keep failing if a pcall catches it
    lua_sethook(vm.L_, count_hook, LUA_MASKCOUNT, 1);  // and in the main thread
    lua_getinfo(L, "Sl", ar);
    char msg[256];  // no C++ object may live across luaL_error's longjmp
    std::snprintf(msg, sizeof msg, "%s", limit_message(limit).c_str());
    luaL_error(L, "%s:%d: %s", ar->short_src, ar->currentline, msg);
  }
}

// coroutine.create / coroutine.wrap: charge kHookEvery, then the original
// (upvalue 1); the new thread inherits the count hook.
int counted_coroutine(lua_State* L) {
  Vm& vm = Vm::of(L);
  char msg[256] = "";  // no C++ object may live across luaL_error's longjmp
  if (const Status st = vm.charge(kHookEvery); !st.is_ok())
    std::snprintf(msg, sizeof msg, "%s", st.message().c_str());
  if (msg[0]) return luaL_error(L, "%s", msg);
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

Status Vm::charge(long long instructions) {
  if (watchdog_ && watchdog_->expired())
    return Status::timeout("stopped: the call ran longer than " + std::to_string(options_.max_seconds) +
                           " s of wall-clock time; raise it with --max-seconds S, or 0 for no limit");
  const long long limit = options_.max_instructions;
  if (limit <= 0) return Status::ok();
  instructions_ += instructions;
  if (stopped_ || instructions_ >= limit) {
    stopped_ = true;
    lua_sethook(L_, count_hook, LUA_MASKCOUNT, 1);
    return Status::error(Code::kInvalidArgument, limit_message(limit));
  }
  return Status::ok();
}

Vm::Call::Call(Vm& vm) : vm_(vm), in_binding_(vm.in_binding_) {
  if (vm_.call_depth_++ == 0) {
    vm_.instructions_ = 0;
    vm_.stopped_ = false;
    const double s = vm_.options_.max_seconds;
    if (s > 0) {
      char msg[200];
      std::snprintf(msg, sizeof msg,
                    "squawk: a script call ran 2 s past --max-seconds %g inside one C function "
                    "(a costly string pattern?); exiting",
                    s);
      vm_.watchdog_ = std::make_unique<Watchdog>(s, 2.0, msg);
    }
    if (vm_.options_.max_instructions > 0 || s > 0)
      lua_sethook(vm_.L_, count_hook, LUA_MASKCOUNT, kHookEvery);
  }
}

Vm::Call::~Call() {
  vm_.in_binding_ = in_binding_;
  if (--vm_.call_depth_ == 0) vm_.watchdog_.reset();
}

Vm& Vm::of(lua_State* L) { return **static_cast<Vm**>(lua_getextraspace(L)); }

Vm::Vm(VmOptions options) : options_(std::move(options)), rng_(options_.seed) {
  if (options_.unsafe) rules_ = paths::PathRules::unrestricted();
  for (const char* rel : {"scripts", "prompts", "scenarios", "envs", "models"}) rules_.allow_read(paths::resource(rel));
  for (const auto* list : {&options_.require_dirs, &options_.read_dirs})
    for (const auto& dir : *list) rules_.allow_read(dir);
  for (const auto* dir : {&options_.out_dir, &options_.navdata_dir}) rules_.allow_read(*dir);
  rules_.allow_write(options_.out_dir);
  L_ = lua_newstate(vm_alloc, this);
  if (!L_) throw std::bad_alloc();
  *static_cast<Vm**>(lua_getextraspace(L_)) = this;
  // Generational collection, a minor cycle after each 10 % of growth: the translator and the
  // environments make short-lived tables per request or step that die young. The incremental
  // collector's full cycles made the tail of a translation's latency (bench_translate: wall p99
  // ~4.6 ms against ~1.1 ms).
  lua_gc(L_, LUA_GCGEN, 10, 0);
  open_sandbox();
  bind_all(L_);
  lua_getglobal(L_, "coroutine");
  for (const char* fn : {"create", "wrap"}) {
    lua_getfield(L_, -1, fn);
    lua_pushcclosure(L_, counted_coroutine, 1);
    lua_setfield(L_, -2, fn);
  }
  lua_pop(L_, 1);
  if (options_.max_instructions > 0) lua_sethook(L_, count_hook, LUA_MASKCOUNT, kHookEvery);
}

Vm::~Vm() {
  if (!L_) return;
  {
    // The finalizers lua_close runs are bounded like a call (see the contract).
    const Call last(*this);
    lua_close(L_);
  }
}

void Vm::open_sandbox() {
  lua_State* L = L_;
  if (options_.unsafe) {
    luaL_openlibs(L);
  } else {
    const luaL_Reg libs[] = {{LUA_GNAME, luaopen_base},       {LUA_LOADLIBNAME, luaopen_package},
                             {LUA_TABLIBNAME, luaopen_table}, {LUA_STRLIBNAME, luaopen_string},
                             {LUA_MATHLIBNAME, luaopen_math}, {LUA_UTF8LIBNAME, luaopen_utf8},
                             {LUA_IOLIBNAME, luaopen_io},     {LUA_OSLIBNAME, luaopen_os},
                             {LUA_COLIBNAME, luaopen_coroutine}};
    for (const auto& lib : libs) {
      luaL_requiref(L, lib.name, lib.func, 1);
      lua_pop(L, 1);
    }
    lua_pushglobaltable(L);
    const int g = lua_gettop(L);
    lua_pushcfunction(L, safe_print);
    lua_setfield(L, g, "print");
    lua_newtable(L);  // squawk.gc_shadows: weak keys
    lua_newtable(L);
    lua_pushliteral(L, "k");
    lua_setfield(L, -2, "__mode");
    lua_setmetatable(L, -2);
    lua_setfield(L, LUA_REGISTRYINDEX, "squawk.gc_shadows");
    lua_getfield(L, g, "setmetatable");
    lua_pushcclosure(L, guarded_setmetatable, 1);
    lua_setfield(L, g, "setmetatable");
    set_forbidden(L, g, "_G", "dofile");
    set_forbidden(L, g, "_G", "loadfile");
    lua_getfield(L, g, "load");
    lua_pushcclosure(L, text_only_load, 1);
    lua_setfield(L, g, "load");

    lua_getfield(L, g, "string");
    for (const char* fn : {"find", "match", "gmatch", "gsub"}) {
      lua_getfield(L, -1, fn);
      lua_pushcclosure(L, charged_pattern, 1);
      lua_setfield(L, -2, fn);
    }
    lua_pop(L, 1);

    lua_getfield(L, g, "os");
    for (const char* fn : {"execute", "exit", "remove", "rename", "tmpname", "setlocale"})
      set_forbidden(L, -1, "os", fn);
    lua_pushcfunction(L, checked_getenv);
    lua_setfield(L, -2, "getenv");
    lua_pop(L, 1);

    lua_getfield(L, g, "io");
    for (const char* fn : {"popen", "tmpfile", "output"}) set_forbidden(L, -1, "io", fn);
    lua_getfield(L, -1, "open");
    lua_pushcclosure(L, checked_open, 1);
    lua_setfield(L, -2, "open");
    for (const char* fn : {"lines", "input"}) {
      lua_getfield(L, -1, fn);
      lua_pushcclosure(L, checked_read, 1);
      lua_setfield(L, -2, fn);
    }
    lua_pop(L, 1);

    lua_getfield(L, g, "package");
    set_forbidden(L, -1, "package", "loadlib");
    lua_pushstring(L, "");
    lua_setfield(L, -2, "cpath");
    lua_pushstring(L, "");
    lua_setfield(L, -2, "path");
    lua_getfield(L, -1, "searchers");  // keep the preload searcher, replace the rest
    const lua_Integer n = luaL_len(L, -1);
    for (lua_Integer i = n; i >= 2; --i) {
      lua_pushnil(L);
      lua_seti(L, -2, i);
    }
    lua_pushcfunction(L, lua_file_searcher);
    lua_seti(L, -2, 2);
    lua_pop(L, 2);
    lua_pop(L, 1);  // globals
  }
  if (options_.unsafe) {  // the shipped scripts stay reachable in unsafe mode too
    lua_getglobal(L, "package");
    lua_getfield(L, -1, "searchers");
    lua_pushcfunction(L, lua_file_searcher);
    lua_seti(L, -2, luaL_len(L, -2) + 1);
    lua_pop(L, 2);
  }
  // Folders for `require`: scripts/, extra folders; run_file adds the script's.
  lua_newtable(L);
  lua_Integer k = 0;
  lua_pushstring(L, paths::resource("scripts").c_str());
  lua_seti(L, -2, ++k);
  for (const auto& d : options_.require_dirs) {
    lua_pushstring(L, d.c_str());
    lua_seti(L, -2, ++k);
  }
  lua_setfield(L, LUA_REGISTRYINDEX, "squawk.require_dirs");
}

Status Vm::pcall(int nargs, int nresults) {
  const Call call(*this);
  lua_State* L = L_;
  const int base = lua_gettop(L) - nargs;
  lua_pushcfunction(L, traceback_handler);
  lua_insert(L, base);
  const int rc = lua_pcall(L, nargs, nresults, base);
  lua_remove(L, base);
  if (rc == LUA_OK) return Status::ok();
  std::string msg = rc == LUA_ERRMEM && memory_refused_ ? memory_message() : error_text(L, -1);
  lua_pop(L, 1);
  return Status::error(Code::kInvalidArgument, msg);
}

Status Vm::run_string(const std::string& code, const std::string& chunkname) {
  if (luaL_loadbufferx(L_, code.data(), code.size(), ("=" + chunkname).c_str(), "t") != LUA_OK) {
    std::string msg = lua_tostring(L_, -1);
    lua_pop(L_, 1);
    return Status::invalid(msg);
  }
  return pcall(0, 0);
}

Status Vm::load_table(const std::string& path, const std::string& key) {
  lua_State* L = L_;
  if (luaL_loadfilex(L, path.c_str(), "t") != LUA_OK) {
    std::string msg = lua_tostring(L, -1);
    lua_pop(L, 1);
    return Status::invalid(msg);
  }
  lua_pushcfunction(L, traceback_handler);
  lua_insert(L, -2);
  const Call call(*this);
  const int rc = lua_pcall(L, 0, 1, -2);
  if (rc != LUA_OK) {
    std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "(error without message)";
    lua_pop(L, 2);
    return Status::invalid(msg);
  }
  if (!lua_istable(L, -1)) {
    std::string got = luaL_typename(L, -1);
    lua_pop(L, 2);
    return Status::invalid(path + ": expected the file to return a table, got " + got);
  }
  lua_setfield(L, LUA_REGISTRYINDEX, key.c_str());
  lua_pop(L, 1);
  return Status::ok();
}

void Vm::add_script_folder(const std::string& dir) {
  lua_State* L = L_;
  lua_getfield(L, LUA_REGISTRYINDEX, "squawk.require_dirs");
  const lua_Integer n = luaL_len(L, -1);
  for (lua_Integer i = n; i >= 1; --i) {
    lua_geti(L, -1, i);
    lua_seti(L, -2, i + 1);
  }
  lua_pushstring(L, dir.c_str());
  lua_seti(L, -2, 1);
  lua_pop(L, 1);
  rules_.allow_read(dir);
}

Status Vm::run_file(const std::string& path, const std::vector<std::string>& args) {
  lua_State* L = L_;
  add_script_folder(paths::dirname(path));

  lua_createtable(L, static_cast<int>(args.size()), 1);
  lua_pushstring(L, path.c_str());
  lua_seti(L, -2, 0);
  for (size_t i = 0; i < args.size(); ++i) {
    lua_pushstring(L, args[i].c_str());
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setglobal(L, "arg");

  if (luaL_loadfilex(L, path.c_str(), "t") != LUA_OK) {
    std::string msg = lua_tostring(L, -1);
    lua_pop(L, 1);
    return Status::invalid(msg);
  }
  // also as `...` (the stack grows to hold them: Lua guarantees only LUA_MINSTACK free slots)
  if (!lua_checkstack(L, static_cast<int>(args.size()) + 1)) {
    lua_pop(L, 1);
    return Status::invalid(path + ": too many arguments (" + std::to_string(args.size()) +
                           ") for the Lua stack");
  }
  for (const auto& a : args) lua_pushstring(L, a.c_str());
  return pcall(static_cast<int>(args.size()), 0);
}

}  // namespace squawk::script
