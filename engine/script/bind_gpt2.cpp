// squawk.gpt2: the GPT-2 model and its tokenizer.
//
//   squawk.gpt2.load(dir | "tiny", [seed = 0]) -> model
//       A Hugging Face GPT-2 folder, or the seeded random tiny model.
//   model:info()                 -> {n_layer=, n_head=, n_embd=, n_ctx=, vocab_size=, params=}
//   model:encode(text)           -> {id, ...} (ids are 0-based, as GPT-2's)
//   model:decode({id, ...})      -> text
//   model:generate(prompt, [{max_tokens = 32, top_k = 40, seed = 0}]) -> continuation
//   model:logits(text)           -> {logit, ...} at the last position; index id + 1
//   model:hidden({{id, ...}, ...}) -> {{h, ...}, ...} final hidden state (after
//       ln_f) of the last token of each sequence, C numbers each
#include <algorithm>

#include "gpt2/bundle.h"
#include "gpt2/generate.h"
#include "script/bindings.h"
#include "script/lua_util.h"

namespace squawk::script {

namespace {

constexpr const char* kModelMt = "squawk.gpt2.Model";

const gpt2::Tokenizer& tokenizer(const gpt2::Bundle& b) {
  auto t = b.text_tokenizer();
  check_status(t.status());
  return **t;
}

void push_ints(lua_State* L, const std::vector<int>& v) {
  lua_createtable(L, static_cast<int>(v.size()), 0);
  for (size_t i = 0; i < v.size(); ++i) {
    lua_pushinteger(L, v[i]);
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

void push_floats(lua_State* L, const float* v, size_t n) {
  lua_createtable(L, static_cast<int>(n), 0);
  for (size_t i = 0; i < n; ++i) {
    lua_pushnumber(L, v[i]);
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

std::vector<int> read_ints(lua_State* L, int idx, const char* name) {
  if (!lua_istable(L, idx)) throw ArgError(type_error(L, idx, name, "table of integers"));
  std::vector<int> out;
  const lua_Integer n = length(L, idx);
  for (lua_Integer i = 1; i <= n; ++i) {
    get_index(L, idx, i);
    int isnum = 0;
    const lua_Integer v = lua_tointegerx(L, -1, &isnum);
    lua_pop(L, 1);
    if (!isnum || v < 0 || v > (1 << 30))
      throw ArgError(std::string(name) + "[" + std::to_string(i) + "]: expected a token id >= 0");
    out.push_back(static_cast<int>(v));
  }
  return out;
}

// Integer field `key` of the table at idx in [lo, 2^30], or fallback when nil.
int bounded_field(lua_State* L, int idx, const char* key, int fallback, int lo) {
  const double v = field_number(L, idx, key, fallback);
  if (!(v >= lo && v <= (1 << 30)) || v != static_cast<double>(static_cast<long long>(v)))
    throw ArgError(std::string(key) + ": expected an integer in " + std::to_string(lo) + "..2^30");
  return static_cast<int>(v);
}

// Charges a forward pass over `tokens` tokens: 2 flops per parameter per
// token, 1000 flops per Lua instruction's worth of budget.
void charge_tokens(lua_State* L, const gpt2::Bundle& b, long long tokens) {
  const long long per_token = std::max(1LL, b.model.config().num_params() / 500);
  charge(L, tokens > (1LL << 62) / per_token ? (1LL << 62) : tokens * per_token);
}

int l_load(lua_State* L) {
  std::string dir = arg_string(L, 1, "dir");
  if (dir != "tiny") dir = readable_folder(L, dir, "model folder");
  const long long seed = opt_integer(L, 2, "seed", 0);
  if (seed < 0) throw ArgError("seed: expected an integer >= 0");
  auto b = gpt2::load_bundle(dir, static_cast<uint64_t>(seed));
  check_status(b.status());
  new_object<gpt2::Bundle>(L, kModelMt, std::move(b).value());
  return 1;
}

int l_info(lua_State* L) {
  const auto* b = arg_object<gpt2::Bundle>(L, 1, kModelMt);
  const gpt2::Config& c = b->model.config();
  lua_createtable(L, 0, 6);
  const std::pair<const char*, long long> fields[] = {
      {"n_layer", c.n_layer}, {"n_head", c.n_head}, {"n_embd", c.n_embd},
      {"n_ctx", c.n_ctx},     {"vocab_size", c.vocab_size}, {"params", c.num_params()}};
  for (const auto& [k, v] : fields) {
    lua_pushinteger(L, v);
    lua_setfield(L, -2, k);
  }
  return 1;
}

int l_encode(lua_State* L) {
  const auto* b = arg_object<gpt2::Bundle>(L, 1, kModelMt);
  auto ids = tokenizer(*b).encode(arg_string(L, 2, "text"));
  check_status(ids.status());
  push_ints(L, *ids);
  return 1;
}

int l_decode(lua_State* L) {
  const auto* b = arg_object<gpt2::Bundle>(L, 1, kModelMt);
  auto text = tokenizer(*b).decode(read_ints(L, 2, "ids"));
  check_status(text.status());
  lua_pushlstring(L, text->data(), text->size());
  return 1;
}

int l_generate(lua_State* L) {
  const auto* b = arg_object<gpt2::Bundle>(L, 1, kModelMt);
  const std::string prompt = arg_string(L, 2, "prompt");
  gpt2::GenerateOptions opt;
  if (lua_istable(L, 3)) {
    opt.max_tokens = bounded_field(L, 3, "max_tokens", opt.max_tokens, 0);
    opt.top_k = bounded_field(L, 3, "top_k", opt.top_k, 1);
    opt.seed = static_cast<uint64_t>(bounded_field(L, 3, "seed", 0, 0));
  }
  charge_tokens(L, *b, static_cast<long long>(prompt.size()) + opt.max_tokens);  // bytes bound tokens
  auto out = gpt2::generate(b->model, tokenizer(*b), prompt, opt);
  check_status(out.status());
  lua_pushlstring(L, out->data(), out->size());
  return 1;
}

int l_logits(lua_State* L) {
  const auto* b = arg_object<gpt2::Bundle>(L, 1, kModelMt);
  auto ids = tokenizer(*b).encode(arg_string(L, 2, "text"));
  check_status(ids.status());
  charge_tokens(L, *b, static_cast<long long>(ids->size()));
  std::vector<float> hidden, out;
  check_status(b->model.forward_last({}, {*ids}, hidden));
  check_status(b->model.lm_logits(hidden, out));
  push_floats(L, out.data(), out.size());
  return 1;
}

int l_hidden(lua_State* L) {
  const auto* b = arg_object<gpt2::Bundle>(L, 1, kModelMt);
  if (!lua_istable(L, 2)) throw ArgError(type_error(L, 2, "seqs", "table of token-id tables"));
  std::vector<std::vector<int>> seqs;
  const lua_Integer n = length(L, 2);
  for (lua_Integer i = 1; i <= n; ++i) {
    get_index(L, 2, i);
    seqs.push_back(read_ints(L, lua_gettop(L), "seqs[i]"));
    lua_pop(L, 1);
  }
  long long tokens = 0;
  for (const auto& q : seqs) tokens += static_cast<long long>(q.size());
  charge_tokens(L, *b, tokens);
  std::vector<float> hidden;
  check_status(b->model.forward_last({}, seqs, hidden));
  const size_t C = static_cast<size_t>(b->model.config().n_embd);
  lua_createtable(L, static_cast<int>(seqs.size()), 0);
  for (size_t i = 0; i < seqs.size(); ++i) {
    push_floats(L, hidden.data() + i * C, C);
    lua_seti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

}  // namespace

void bind_gpt2(lua_State* L) {
  const luaL_Reg methods[] = {{"info", guarded<l_info>},       {"encode", guarded<l_encode>},
                              {"decode", guarded<l_decode>},   {"generate", guarded<l_generate>},
                              {"logits", guarded<l_logits>},   {"hidden", guarded<l_hidden>},
                              {nullptr, nullptr}};
  define_class(L, kModelMt, methods);
  push_squawk_subtable(L, "gpt2");
  lua_pushcfunction(L, guarded<l_load>);
  lua_setfield(L, -2, "load");
  lua_pop(L, 1);
}

}  // namespace squawk::script
