// GCC 12 reports -Wmaybe-uninitialized falsely inside Eigen's AVX-512 product kernels.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "nn/attention.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

namespace squawk::nn {

namespace {

using RowMat = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstMap = Eigen::Map<const RowMat, 0, Eigen::OuterStride<>>;
using MutMap = Eigen::Map<RowMat, 0, Eigen::OuterStride<>>;

// One attention problem: nq queries (rows q0.. of qkv) over nc context keys
// (ctx_k/ctx_v with row stride ctx_stride) followed by their own keys, causal.
struct Group {
  int q0 = 0, nq = 0, nc = 0;
  const float* ctx_k = nullptr;
  const float* ctx_v = nullptr;
  int ctx_stride = 0;
  bool ctx_is_inline = false;  // context rows are rows 0..nc-1 of qkv
  size_t att_offset = 0;       // start of this group's [NH, nq, nc+nq] probabilities
};

std::vector<Group> groups(const float* qkv, const float* k_ext, const float* v_ext, int ext_stride,
                          const AttentionShape& s) {
  std::vector<Group> g;
  const int C = s.C;
  size_t att = 0;
  int row = 0;
  if (s.inline_prefix && s.P > 0) {
    g.push_back({0, s.P, 0, nullptr, nullptr, 0, false, 0});
    att += static_cast<size_t>(s.NH) * s.P * s.P;
    row = s.P;
  }
  for (int b = 0; b < s.B; ++b) {
    Group gr{row, s.T, s.P, nullptr, nullptr, 0, false, att};
    if (s.P > 0) {
      if (s.inline_prefix) {
        gr.ctx_k = qkv + C;
        gr.ctx_v = qkv + 2 * C;
        gr.ctx_stride = 3 * C;
        gr.ctx_is_inline = true;
      } else {
        gr.ctx_k = k_ext;
        gr.ctx_v = v_ext;
        gr.ctx_stride = ext_stride;
      }
    }
    g.push_back(gr);
    att += static_cast<size_t>(s.NH) * s.T * (s.P + s.T);
    row += s.T;
  }
  return g;
}

}  // namespace

size_t attention_probs_size(const AttentionShape& s) {
  size_t n = static_cast<size_t>(s.B) * s.NH * s.T * (s.P + s.T);
  if (s.inline_prefix) n += static_cast<size_t>(s.NH) * s.P * s.P;
  return n;
}

void attention_forward(float* out, float* att, const float* qkv, const float* k_ext,
                       const float* v_ext, int ext_stride, const AttentionShape& s) {
  const int C = s.C, C3 = 3 * C, hs = C / s.NH;
  const float scale = 1.0f / std::sqrt(static_cast<float>(hs));
  RowMat S;
  for (const Group& g : groups(qkv, k_ext, v_ext, ext_stride, s)) {
    const int nq = g.nq, nc = g.nc, nk = nc + nq;
    for (int h = 0; h < s.NH; ++h) {
      const float* base = qkv + static_cast<long>(g.q0) * C3 + h * hs;
      ConstMap Q(base, nq, hs, Eigen::OuterStride<>(C3));
      ConstMap Ks(base + C, nq, hs, Eigen::OuterStride<>(C3));
      ConstMap Vs(base + 2 * C, nq, hs, Eigen::OuterStride<>(C3));
      S.resize(nq, nk);
      if (nc > 0) {
        ConstMap Kc(g.ctx_k + h * hs, nc, hs, Eigen::OuterStride<>(g.ctx_stride));
        S.leftCols(nc).noalias() = scale * (Q * Kc.transpose());
      }
      S.rightCols(nq).noalias() = scale * (Q * Ks.transpose());
      for (int i = 0; i < nq; ++i) {
        const int valid = nc + i + 1;
        auto row = S.row(i).head(valid).array();
        row = (row - row.maxCoeff()).exp();
        row /= row.sum();
        S.row(i).tail(nk - valid).setZero();
      }
      MutMap O(out + static_cast<long>(g.q0) * C + h * hs, nq, hs, Eigen::OuterStride<>(C));
      O.noalias() = S.rightCols(nq) * Vs;
      if (nc > 0) {
        ConstMap Vc(g.ctx_v + h * hs, nc, hs, Eigen::OuterStride<>(g.ctx_stride));
        O.noalias() += S.leftCols(nc) * Vc;
      }
      if (att) {
        Eigen::Map<RowMat>(att + g.att_offset + static_cast<size_t>(h) * nq * nk, nq, nk) = S;
      }
    }
  }
}

void attention_backward(float* dqkv, const float* dout, const float* att, const float* qkv,
                        const float* k_ext, const float* v_ext, int ext_stride,
                        const AttentionShape& s) {
  const int C = s.C, C3 = 3 * C, hs = C / s.NH;
  const float scale = 1.0f / std::sqrt(static_cast<float>(hs));
  RowMat dA, dS;
  for (const Group& g : groups(qkv, k_ext, v_ext, ext_stride, s)) {
    const int nq = g.nq, nc = g.nc, nk = nc + nq;
    for (int h = 0; h < s.NH; ++h) {
      const long off = static_cast<long>(g.q0) * C3 + h * hs;
      ConstMap Q(qkv + off, nq, hs, Eigen::OuterStride<>(C3));
      ConstMap Ks(qkv + off + C, nq, hs, Eigen::OuterStride<>(C3));
      ConstMap Vs(qkv + off + 2 * C, nq, hs, Eigen::OuterStride<>(C3));
      MutMap dQ(dqkv + off, nq, hs, Eigen::OuterStride<>(C3));
      MutMap dKs(dqkv + off + C, nq, hs, Eigen::OuterStride<>(C3));
      MutMap dVs(dqkv + off + 2 * C, nq, hs, Eigen::OuterStride<>(C3));
      ConstMap dO(dout + static_cast<long>(g.q0) * C + h * hs, nq, hs, Eigen::OuterStride<>(C));
      Eigen::Map<const RowMat> A(att + g.att_offset + static_cast<size_t>(h) * nq * nk, nq, nk);
      dA.resize(nq, nk);
      dA.rightCols(nq).noalias() = dO * Vs.transpose();
      if (nc > 0) {
        ConstMap Vc(g.ctx_v + h * hs, nc, hs, Eigen::OuterStride<>(g.ctx_stride));
        dA.leftCols(nc).noalias() = dO * Vc.transpose();
      }
      // Softmax backward: dS = A .* (dA - rowsum(A .* dA)), then the 1/sqrt(hs) scale.
      dS.resize(nq, nk);
      for (int i = 0; i < nq; ++i) {
        const float dot = A.row(i).dot(dA.row(i));
        dS.row(i) = scale * (A.row(i).array() * (dA.row(i).array() - dot)).matrix();
      }
      dVs.noalias() += A.rightCols(nq).transpose() * dO;
      dQ.noalias() += dS.rightCols(nq) * Ks;
      dKs.noalias() += dS.rightCols(nq).transpose() * Q;
      if (nc > 0) {
        ConstMap Kc(g.ctx_k + h * hs, nc, hs, Eigen::OuterStride<>(g.ctx_stride));
        dQ.noalias() += dS.leftCols(nc) * Kc;
        if (g.ctx_is_inline) {
          MutMap dKc(dqkv + C + h * hs, nc, hs, Eigen::OuterStride<>(C3));
          MutMap dVc(dqkv + 2 * C + h * hs, nc, hs, Eigen::OuterStride<>(C3));
          dKc.noalias() += dS.leftCols(nc).transpose() * Q;
          dVc.noalias() += A.leftCols(nc).transpose() * dO;
        }
      }
    }
  }
}

namespace {

// The group (sequence block) of query row r; rows of an inline prefix are no
// query rows here.
const Group& group_of(const std::vector<Group>& gs, int r, const AttentionShape& s) {
  const int lead = s.inline_prefix && s.P > 0 ? 1 : 0;
  return gs[static_cast<size_t>(lead + (r - lead * s.P) / s.T)];
}

// Calls fn(q, r, g, nown, h) for query q (row r = rows[q] of group g, which
// sees nown of its own keys) and every head h.
template <class F>
void each_query_head(std::span<const int> rows, const std::vector<Group>& gs,
                     const AttentionShape& s, F&& fn) {
  for (size_t q = 0; q < rows.size(); ++q) {
    const Group& g = group_of(gs, rows[q], s);
    for (int h = 0; h < s.NH; ++h) fn(q, rows[q], g, rows[q] - g.q0 + 1, h);
  }
}

using Vec = Eigen::Matrix<float, Eigen::Dynamic, 1>;
using ConstRowVec = Eigen::Map<const Eigen::Matrix<float, 1, Eigen::Dynamic>>;
using MutRowVec = Eigen::Map<Eigen::Matrix<float, 1, Eigen::Dynamic>>;

}  // namespace

size_t attention_rows_probs_size(const AttentionShape& s, int Q) {
  return static_cast<size_t>(Q) * s.NH * (s.P + s.T);
}

void attention_forward_rows(float* out, float* att, const float* qkv, const float* k_ext,
                            const float* v_ext, int ext_stride, const AttentionShape& s,
                            std::span<const int> rows) {
  const int C = s.C, C3 = 3 * C, hs = C / s.NH, width = s.P + s.T;
  const float scale = 1.0f / std::sqrt(static_cast<float>(hs));
  Vec w;
  auto one = [&](size_t q, int r, const Group& v, int nown, int h) {
    const int nk = v.nc + nown;
    ConstRowVec qv(qkv + static_cast<long>(r) * C3 + h * hs, hs);
    const float* own = qkv + static_cast<long>(v.q0) * C3 + h * hs;
    ConstMap Ks(own + C, nown, hs, Eigen::OuterStride<>(C3));
    ConstMap Vs(own + 2 * C, nown, hs, Eigen::OuterStride<>(C3));
    w.resize(nk);
    if (v.nc > 0) {
      ConstMap Kc(v.ctx_k + h * hs, v.nc, hs, Eigen::OuterStride<>(v.ctx_stride));
      w.head(v.nc).noalias() = scale * (Kc * qv.transpose());
    }
    w.tail(nown).noalias() = scale * (Ks * qv.transpose());
    w = (w.array() - w.maxCoeff()).exp();
    w /= w.sum();
    MutRowVec o(out + q * C + h * hs, hs);
    o.noalias() = w.tail(nown).transpose() * Vs;
    if (v.nc > 0) {
      ConstMap Vc(v.ctx_v + h * hs, v.nc, hs, Eigen::OuterStride<>(v.ctx_stride));
      o.noalias() += w.head(v.nc).transpose() * Vc;
    }
    if (att) {
      float* a = att + (q * s.NH + h) * static_cast<size_t>(width);
      std::copy(w.data(), w.data() + nk, a);
      std::fill(a + nk, a + width, 0.0f);
    }
  };
  each_query_head(rows, groups(qkv, k_ext, v_ext, ext_stride, s), s, one);
}

void attention_backward_rows(float* dqkv, const float* dout, const float* att, const float* qkv,
                             const float* k_ext, const float* v_ext, int ext_stride,
                             const AttentionShape& s, std::span<const int> rows) {
  const int C = s.C, C3 = 3 * C, hs = C / s.NH, width = s.P + s.T;
  const float scale = 1.0f / std::sqrt(static_cast<float>(hs));
  Vec dA, dS;
  auto one = [&](size_t q, int r, const Group& v, int nown, int h) {
    const int nk = v.nc + nown;
    ConstRowVec qv(qkv + static_cast<long>(r) * C3 + h * hs, hs);
    ConstRowVec dO(dout + q * C + h * hs, hs);
    Eigen::Map<const Vec> A(att + (q * s.NH + h) * static_cast<size_t>(width), nk);
    const long own = static_cast<long>(v.q0) * C3 + h * hs;
    ConstMap Ks(qkv + own + C, nown, hs, Eigen::OuterStride<>(C3));
    ConstMap Vs(qkv + own + 2 * C, nown, hs, Eigen::OuterStride<>(C3));
    MutMap dKs(dqkv + own + C, nown, hs, Eigen::OuterStride<>(C3));
    MutMap dVs(dqkv + own + 2 * C, nown, hs, Eigen::OuterStride<>(C3));
    MutRowVec dq(dqkv + static_cast<long>(r) * C3 + h * hs, hs);
    dA.resize(nk);
    dA.tail(nown).noalias() = Vs * dO.transpose();
    if (v.nc > 0) {
      ConstMap Vc(v.ctx_v + h * hs, v.nc, hs, Eigen::OuterStride<>(v.ctx_stride));
      dA.head(v.nc).noalias() = Vc * dO.transpose();
    }
    // Softmax backward, then the 1/sqrt(hs) scale.
    dS = scale * (A.array() * (dA.array() - A.dot(dA))).matrix();
    dVs.noalias() += A.tail(nown) * dO;
    dKs.noalias() += dS.tail(nown) * qv;
    dq.noalias() += dS.tail(nown).transpose() * Ks;
    if (v.nc > 0) {
      ConstMap Kc(v.ctx_k + h * hs, v.nc, hs, Eigen::OuterStride<>(v.ctx_stride));
      dq.noalias() += dS.head(v.nc).transpose() * Kc;
      if (v.ctx_is_inline) {
        MutMap dKc(dqkv + C + h * hs, v.nc, hs, Eigen::OuterStride<>(C3));
        MutMap dVc(dqkv + 2 * C + h * hs, v.nc, hs, Eigen::OuterStride<>(C3));
        dKc.noalias() += dS.head(v.nc) * qv;
        dVc.noalias() += A.head(v.nc) * dO;
      }
    }
  };
  each_query_head(rows, groups(qkv, k_ext, v_ext, ext_stride, s), s, one);
}

void attention_forward_ref(float* out, float* att, const float* qkv, const float* k_ext,
                           const float* v_ext, int ext_stride, const AttentionShape& s) {
  const int C = s.C, C3 = 3 * C, hs = C / s.NH;
  const double scale = 1.0 / std::sqrt(static_cast<double>(hs));
  std::vector<double> w;
  for (const Group& g : groups(qkv, k_ext, v_ext, ext_stride, s)) {
    const int nq = g.nq, nc = g.nc, nk = nc + nq;
    for (int h = 0; h < s.NH; ++h) {
      for (int i = 0; i < nq; ++i) {
        const float* q = qkv + static_cast<long>(g.q0 + i) * C3 + h * hs;
        auto key = [&](int j) {
          return j < nc ? g.ctx_k + static_cast<long>(j) * g.ctx_stride + h * hs
                        : qkv + static_cast<long>(g.q0 + j - nc) * C3 + C + h * hs;
        };
        auto val = [&](int j) {
          return j < nc ? g.ctx_v + static_cast<long>(j) * g.ctx_stride + h * hs
                        : qkv + static_cast<long>(g.q0 + j - nc) * C3 + 2 * C + h * hs;
        };
        w.assign(nk, 0.0);
        double mx = -1e300, sum = 0.0;
        for (int j = 0; j <= nc + i; ++j) {
          double d = 0.0;
          for (int e = 0; e < hs; ++e) d += static_cast<double>(q[e]) * key(j)[e];
          w[j] = d * scale;
          mx = std::max(mx, w[j]);
        }
        for (int j = 0; j <= nc + i; ++j) sum += (w[j] = std::exp(w[j] - mx));
        for (int j = 0; j <= nc + i; ++j) w[j] /= sum;
        float* o = out + static_cast<long>(g.q0 + i) * C + h * hs;
        for (int e = 0; e < hs; ++e) {
          double acc = 0.0;
          for (int j = 0; j <= nc + i; ++j) acc += w[j] * val(j)[e];
          o[e] = static_cast<float>(acc);
        }
        if (att) {
          float* a = att + g.att_offset + (static_cast<size_t>(h) * nq + i) * nk;
          for (int j = 0; j < nk; ++j) a[j] = static_cast<float>(w[j]);
        }
      }
    }
  }
}

void attention_backward_ref(float* dqkv, const float* dout, const float* att, const float* qkv,
                            const float* k_ext, const float* v_ext, int ext_stride,
                            const AttentionShape& s) {
  const int C = s.C, C3 = 3 * C, hs = C / s.NH;
  const double scale = 1.0 / std::sqrt(static_cast<double>(hs));
  std::vector<double> da;
  for (const Group& g : groups(qkv, k_ext, v_ext, ext_stride, s)) {
    const int nq = g.nq, nc = g.nc, nk = nc + nq;
    auto row_of = [&](int j) { return j < nc ? j : g.q0 + j - nc; };
    for (int h = 0; h < s.NH; ++h) {
      for (int i = 0; i < nq; ++i) {
        const long qrow = static_cast<long>(g.q0 + i) * C3 + h * hs;
        const float* a = att + g.att_offset + (static_cast<size_t>(h) * nq + i) * nk;
        const float* dout_i = dout + static_cast<long>(g.q0 + i) * C + h * hs;
        const int valid = nc + i + 1;
        da.assign(nk, 0.0);
        double dot = 0.0;
        for (int j = 0; j < valid; ++j) {
          const float* v = j < nc ? g.ctx_v + static_cast<long>(j) * g.ctx_stride + h * hs
                                  : qkv + static_cast<long>(row_of(j)) * C3 + 2 * C + h * hs;
          for (int e = 0; e < hs; ++e) da[j] += static_cast<double>(dout_i[e]) * v[e];
          dot += da[j] * a[j];
        }
        for (int j = 0; j < valid; ++j) {
          const double ds = a[j] * (da[j] - dot) * scale;
          const bool ctx = j < nc;
          const float* k = ctx ? g.ctx_k + static_cast<long>(j) * g.ctx_stride + h * hs
                               : qkv + static_cast<long>(row_of(j)) * C3 + C + h * hs;
          const bool grads_to_key = !ctx || g.ctx_is_inline;
          const long krow = static_cast<long>(row_of(j)) * C3 + h * hs;
          for (int e = 0; e < hs; ++e) {
            dqkv[qrow + e] += static_cast<float>(ds * k[e]);
            if (grads_to_key) {
              dqkv[krow + C + e] += static_cast<float>(ds * qkv[qrow + e]);
              dqkv[krow + 2 * C + e] += static_cast<float>(a[j] * dout_i[e]);
            }
          }
        }
      }
    }
  }
}

}  // namespace squawk::nn
