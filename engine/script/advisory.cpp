#include "script/advisory.h"

#include "script/advisory_fields.h"
#include "script/lua_fields.h"
#include "script/lua_util.h"
#include "script/vm.h"

namespace squawk::script {

namespace {
constexpr const char* kModuleKey = "squawk.advisory";
}

Result<AdvisoryPhraser> AdvisoryPhraser::load(const std::string& path, const VmOptions& options) {
  AdvisoryPhraser p;
  p.vm_ = std::make_shared<Vm>(options);
  SQUAWK_RETURN_IF_ERROR(p.vm_->load_table(path, kModuleKey));
  lua_State* L = p.vm_->state();
  bool ok = false;
  SQUAWK_RETURN_IF_ERROR(catch_arg_errors(L, path + ": ", [&] {
    lua_getfield(L, LUA_REGISTRYINDEX, kModuleKey);
    ok = get_field(L, -1, "advise") == LUA_TFUNCTION;
    lua_pop(L, 2);
  }));
  if (!ok) return Status::invalid(path + ": the returned table has no function advise(d)");
  return p;
}

Result<std::string> AdvisoryPhraser::phrase(const Advisory& a) {
  lua_State* L = vm_->state();
  const int top = lua_gettop(L);
  SQUAWK_RETURN_IF_ERROR(catch_arg_errors(L, "advise(): ", [&] {
    lua_getfield(L, LUA_REGISTRYINDEX, kModuleKey);
    get_field(L, -1, "advise");
    lua_remove(L, -2);
  }));
  push_fields(L, fields::kAdvisory, a);
  if (a.traffic) {
    push_fields(L, fields::kAdvisoryTraffic, *a.traffic);
    lua_setfield(L, -2, "traffic");
  }
  std::string out;
  Status st = vm_->pcall(1, 1);
  if (!st.is_ok()) {
    st = Status::invalid("advise(): " + st.message());
  } else if (lua_type(L, -1) != LUA_TSTRING || lua_rawlen(L, -1) == 0) {
    st = Status::invalid(std::string("advise() must return a non-empty string, got ") +
                         luaL_typename(L, -1));
  } else {
    out = lua_tostring(L, -1);
  }
  lua_settop(L, top);
  if (!st.is_ok()) return st;
  return out;
}

}  // namespace squawk::script
