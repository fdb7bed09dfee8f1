#include "gpt2/config.h"

namespace squawk::gpt2 {

namespace {
Status out_of_range(const char* field, long long got, const char* expected) {
  std::string msg = "gpt2 config: ";
  msg.append(field).append(" = ").append(std::to_string(got)).append(", expected ").append(expected);
  return Status::invalid(msg);
}
}  // namespace

Status Config::validate() const {
  if (n_layer < 1 || n_layer > 256) return out_of_range("n_layer", n_layer, "1..256");
  if (n_head < 1 || n_head > 256) return out_of_range("n_head", n_head, "1..256");
  if (n_embd < 1 || n_embd > 16384 || n_embd % n_head != 0)
    return out_of_range("n_embd", n_embd, "1..16384 and a multiple of n_head");
  if (n_ctx < 1 || n_ctx > 65536) return out_of_range("n_ctx", n_ctx, "1..65536");
  if (vocab_size < 1 || vocab_size > 1000000)
    return out_of_range("vocab_size", vocab_size, "1..1000000");
  if (!(ln_eps > 0.0f && ln_eps < 1.0f))
    return Status::invalid("gpt2 config: layer_norm_epsilon must lie in (0, 1)");
  return Status::ok();
}

long long Config::num_params() const {
  const long long C = n_embd;
  const long long per_block = 2 * C + (C * 3 * C + 3 * C) + (C * C + C) + 2 * C +
                              (C * 4 * C + 4 * C) + (4 * C * C + C);
  return static_cast<long long>(vocab_size) * C + static_cast<long long>(n_ctx) * C +
         n_layer * per_block + 2 * C;
}

}  // namespace squawk::gpt2
