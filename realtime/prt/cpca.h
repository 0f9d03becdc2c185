// Clustered principal component analysis (CPCA; Sloan, Hall, Hart & Snyder, "Clustered principal
// components for precomputed radiance transfer", SIGGRAPH 2003), the compression of PRT's
// transfer vectors in book §8.3, eq. 8.5: each of N vectors of dimension D belongs to one of K
// clusters and is approximated as its cluster's mean plus M weighted basis vectors of that
// cluster, x̂ = M_k + Σ_d w_d B_d^k.
//
// The clusters come from K-means (Lloyd's iterations) seeded by k-means++ (Arthur & Vassilvitskii
// 2007) with SplitMix64 draws from `seed`; each cluster's basis is the top M eigenvectors of its
// scatter matrix Σ (x − M_k)(x − M_k)ᵀ by cyclic Jacobi rotations, the weights the projections
// onto them. Single-threaded and in double inside: the result is a function of the input and
// the seed alone.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace gib::rt::prt {

struct CpcaResult {
  int dimension = 0;                  // D
  int pca_vectors = 0;                // M
  int clusters = 0;                   // K
  std::vector<std::int32_t> cluster;  // N: the cluster of each vector
  std::vector<float> means;           // K × D
  // K × M × D: cluster k's basis vector d at (k·M + d)·D, orthonormal, by decreasing eigenvalue.
  std::vector<float> bases;
  std::vector<float> weights;  // N × M: vector i's weight d at i·M + d

  std::size_t vectorCount() const { return cluster.size(); }
};

// Throws gib::InputError, naming the parameter and the fix, for dimension < 1, a vector span
// that is not a whole number of vectors or holds none, a non-finite value, clusters < 1 or more
// clusters than vectors, pca_vectors < 0 or > dimension.
CpcaResult compressCpca(std::span<const float> vectors, int dimension, int clusters,
                        int pca_vectors, std::uint64_t seed);

// x̂_i = M_k + Σ_d w_d B_d^k of vector `index` into out (dimension values).
void reconstructVector(const CpcaResult& result, std::size_t index, std::span<float> out);
// Every x̂_i, N × D.
std::vector<float> reconstruct(const CpcaResult& result);

// Σ‖x_i − x̂_i‖² / Σ‖x_i‖² in double (0 for an all-zero input reconstructed exactly).
double cpcaRelativeError(std::span<const float> vectors, const CpcaResult& result);

}  // namespace gib::rt::prt
