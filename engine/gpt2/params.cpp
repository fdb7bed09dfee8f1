#include "gpt2/params.h"

#include "core/text.h"

namespace squawk::gpt2 {

Result<ParamLayout> ParamLayout::build(const Config& cfg, const std::vector<TensorSpec>& extras) {
  SQUAWK_RETURN_IF_ERROR(cfg.validate());
  ParamLayout p;
  p.cfg_ = cfg;
  const int64_t C = cfg.n_embd, V = cfg.vocab_size, maxT = cfg.n_ctx;
  size_t off = 0;
  auto add = [&](std::string name, std::vector<int64_t> shape) {
    size_t n = 1;
    for (int64_t d : shape) n *= static_cast<size_t>(d);
    p.index_[name] = p.tensors_.size();
    p.tensors_.push_back({std::move(name), std::move(shape), off, n});
    off += n;
    return off - n;
  };
  add("wte.weight", {V, C});
  add("wpe.weight", {maxT, C});
  p.blocks_start_ = off;
  for (int l = 0; l < cfg.n_layer; ++l) {
    std::string h = "h.";
    h.append(std::to_string(l)).append(".");
    const size_t s = off;
    BlockOffsets b{};
    b.ln1_w = add(h + "ln_1.weight", {C}) - s;
    b.ln1_b = add(h + "ln_1.bias", {C}) - s;
    b.attn_w = add(h + "attn.c_attn.weight", {C, 3 * C}) - s;
    b.attn_b = add(h + "attn.c_attn.bias", {3 * C}) - s;
    b.proj_w = add(h + "attn.c_proj.weight", {C, C}) - s;
    b.proj_b = add(h + "attn.c_proj.bias", {C}) - s;
    b.ln2_w = add(h + "ln_2.weight", {C}) - s;
    b.ln2_b = add(h + "ln_2.bias", {C}) - s;
    b.fc_w = add(h + "mlp.c_fc.weight", {C, 4 * C}) - s;
    b.fc_b = add(h + "mlp.c_fc.bias", {4 * C}) - s;
    b.fcproj_w = add(h + "mlp.c_proj.weight", {4 * C, C}) - s;
    b.fcproj_b = add(h + "mlp.c_proj.bias", {C}) - s;
    b.size = off - s;
    p.block_ = b;
  }
  add("ln_f.weight", {C});
  add("ln_f.bias", {C});
  for (const TensorSpec& e : extras) {
    if (e.name.empty()) return Status::invalid("gpt2 params: an extra tensor has an empty name");
    if (p.index_.count(e.name))
      return Status::invalid("gpt2 params: extra tensor " + text::quoted(e.name) +
                             " clashes with an existing tensor name");
    if (e.shape.empty()) return Status::invalid("gpt2 params: extra tensor " + text::quoted(e.name) + " has no shape");
    for (int64_t d : e.shape)
      if (d < 1 || d > (int64_t{1} << 31))
        return Status::invalid("gpt2 params: extra tensor " + text::quoted(e.name) +
                               " has a dimension outside 1..2^31");
    add(e.name, e.shape);
  }
  p.total_ = off;
  return p;
}

const TensorSpec* ParamLayout::find(const std::string& name) const {
  auto it = index_.find(name);
  return it == index_.end() ? nullptr : &tensors_[it->second];
}

}  // namespace squawk::gpt2
