#include "script/prompt_renderer.h"

#include <lua.hpp>

#include "core/files.h"
#include "script/lua_fields.h"
#include "script/lua_util.h"
#include "script/observation_fields.h"
#include "script/vm.h"

namespace squawk::script {


Result<std::shared_ptr<PromptRenderer>> PromptRenderer::load(const std::string& path,
                                                             const VmOptions& options) {
  if (!files::exists(path)) return Status::not_found("no prompt template file '" + path + "'");
  std::shared_ptr<PromptRenderer> r(new PromptRenderer(path, std::make_unique<Vm>(options)));
  lua_State* L = r->vm_->state();
  const int base = lua_gettop(L);
  if (luaL_loadfilex(L, path.c_str(), "t") != LUA_OK) {
    std::string msg = error_text(L, -1);
    lua_settop(L, base);
    return Status::invalid("prompt template " + path + ": " + msg);
  }
  if (Status st = r->vm_->pcall(0, 1); !st.is_ok()) {
    lua_settop(L, base);
    return Status::invalid("prompt template " + path + ": " + st.message());
  }
  if (!lua_istable(L, -1)) {
    std::string t = luaL_typename(L, -1);
    lua_settop(L, base);
    return Status::invalid("prompt template " + path + " returned " + t +
                           ", expected a table with `prefix` and `render`");
  }
  std::string problem;
  SQUAWK_RETURN_IF_ERROR(catch_arg_errors(L, "prompt template " + path + ": ", [&] {
    get_field(L, -1, "prefix");
    if (!lua_isstring(L, -1)) {
      problem = "field `prefix` must be a string";
      return;
    }
    r->prefix_ = lua_tostring(L, -1);
    lua_pop(L, 1);
    get_field(L, -1, "render");
    if (!lua_isfunction(L, -1)) problem = "field `render` must be a function";
  }));
  if (!problem.empty()) {
    lua_settop(L, base);
    return Status::invalid("prompt template " + path + ": " + problem);
  }
  r->render_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_settop(L, base);
  return r;
}

void push_observation(lua_State* L, const env::Observation& obs) {
  push_fields(L, fields::kObservation, obs);
}

PromptRenderer::~PromptRenderer() {
  if (vm_ && render_ref_ >= 0) luaL_unref(vm_->state(), LUA_REGISTRYINDEX, render_ref_);
}

Result<std::string> PromptRenderer::render(const env::Observation& obs) {
  lua_State* L = vm_->state();
  const int base = lua_gettop(L);
  lua_rawgeti(L, LUA_REGISTRYINDEX, render_ref_);
  push_observation(L, obs);
  if (Status st = vm_->pcall(1, 1); !st.is_ok()) {
    lua_settop(L, base);
    return Status::invalid("prompt template " + path_ + ": render failed: " + st.message());
  }
  if (!lua_isstring(L, -1)) {
    std::string t = luaL_typename(L, -1);
    lua_settop(L, base);
    return Status::invalid("prompt template " + path_ + ": render returned " + t + ", expected a string");
  }
  std::string text = lua_tostring(L, -1);
  lua_settop(L, base);
  if (text.compare(0, prefix_.size(), prefix_) != 0)
    return Status::invalid("prompt template " + path_ + ": the rendered prompt does not start with `prefix`");
  return text;
}

}  // namespace squawk::script
