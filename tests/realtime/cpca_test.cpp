// Clustered PCA (realtime/prt/cpca.h) on data with a known answer: K well-separated clusters,
// each exactly its mean plus M orthogonal directions with sample-uncorrelated weights, so the
// scatter matrix of cluster k has the eigenvalues s_{k,d}²·n/2 along its directions. Then M
// vectors reconstruct it exactly, M − 1 drop exactly the smallest eigenvalue of each cluster,
// and 0 drop all of them; plus determinism and refused parameters.
#include "realtime/prt/cpca.h"
#include "common/input_error.h"
#include "common/splitmix.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace gib::rt::prt {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kDimension = 12, kClusters = 4, kRank = 3, kPerCluster = 50;

double draw(std::uint64_t seed, std::uint64_t i) {
  return double(splitMix64(seed + i * kGoldenGamma) >> 11) * 0x1p-53 * 2 - 1;
}

struct Synthetic {
  std::vector<float> vectors;  // kClusters × kPerCluster vectors, cluster after cluster
  std::vector<double> spread;  // s_{k,d}, kClusters × kRank
};

// Cluster k: mean 60·e_k (means ≥ 84 apart, spreads ≤ 4, so K-means cannot mix clusters);
// point p = mean + Σ_d s_{k,d} cos(2π(d+1)p/n + k) u_{k,d} with u_{k,·} orthonormal (Gram–
// Schmidt of random vectors). Over p = 0..n−1 the cosines of frequencies 1..kRank < n/2 have
// zero sum and are mutually orthogonal with squared norm n/2: the sample mean is the mean and
// the scatter matrix is Σ_d s_{k,d}²·n/2·u_d u_dᵀ exactly.
Synthetic makeSynthetic() {
  Synthetic data;
  std::uint64_t counter = 0;
  for (int k = 0; k < kClusters; ++k) {
    std::vector<std::vector<double>> u;
    for (int d = 0; d < kRank; ++d) {
      std::vector<double> v(kDimension);
      for (double& x : v) x = draw(1, counter++);
      for (const auto& previous : u) {
        double dot = 0;
        for (int c = 0; c < kDimension; ++c) dot += v[std::size_t(c)] * previous[std::size_t(c)];
        for (int c = 0; c < kDimension; ++c) v[std::size_t(c)] -= dot * previous[std::size_t(c)];
      }
      double norm = 0;
      for (double x : v) norm += x * x;
      for (double& x : v) x /= std::sqrt(norm);
      u.push_back(v);
      data.spread.push_back((3.0 - d) * (1 + 0.1 * k));  // distinct: 3, 2, 1 scaled
    }
    for (int p = 0; p < kPerCluster; ++p)
      for (int c = 0; c < kDimension; ++c) {
        double x = c == k ? 60.0 : 0.0;
        for (int d = 0; d < kRank; ++d)
          x += data.spread[std::size_t(k * kRank + d)] *
               std::cos(2 * kPi * (d + 1) * p / kPerCluster + k) *
               u[std::size_t(d)][std::size_t(c)];
        data.vectors.push_back(float(x));
      }
  }
  return data;
}

double sumOfSquares(const std::vector<float>& v) {
  double sum = 0;
  for (float x : v) sum += double(x) * double(x);
  return sum;
}

TEST(Cpca, ExactClustersOfRankMAreReconstructedAndTheirClustersFound) {
  // Rank-M clusters with M basis vectors: only float rounding of data, means and bases remains,
  // a relative squared error of order (1e-7)²; 1e-12 bounds it with margin (the brief's 1e-6
  // is far looser).
  constexpr double kExact = 1e-12;
  const Synthetic data = makeSynthetic();
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    const CpcaResult result = compressCpca(data.vectors, kDimension, kClusters, kRank, seed);
    ASSERT_EQ(result.vectorCount(), std::size_t(kClusters * kPerCluster));
    EXPECT_LT(cpcaRelativeError(data.vectors, result), kExact) << seed;
    // Every true cluster is one found cluster, and no two share one.
    std::vector<int> found(kClusters, -1);
    for (int k = 0; k < kClusters; ++k) {
      found[std::size_t(k)] = result.cluster[std::size_t(k * kPerCluster)];
      for (int p = 0; p < kPerCluster; ++p)
        EXPECT_EQ(result.cluster[std::size_t(k * kPerCluster + p)], found[std::size_t(k)]);
      for (int j = 0; j < k; ++j) EXPECT_NE(found[std::size_t(j)], found[std::size_t(k)]);
    }
    // Bases orthonormal (float rounding, 1e-6).
    for (int k = 0; k < kClusters; ++k)
      for (int a = 0; a < kRank; ++a)
        for (int b = 0; b < kRank; ++b) {
          double dot = 0;
          for (int c = 0; c < kDimension; ++c)
            dot += double(result.bases[std::size_t((k * kRank + a) * kDimension + c)]) *
                   double(result.bases[std::size_t((k * kRank + b) * kDimension + c)]);
          EXPECT_NEAR(dot, a == b ? 1.0 : 0.0, 1e-6);
        }
    // reconstruct() agrees with the error's own reconstruction.
    const std::vector<float> x = reconstruct(result);
    double error = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      error += (double(x[i]) - data.vectors[i]) * (double(x[i]) - data.vectors[i]);
    EXPECT_LT(error / sumOfSquares(data.vectors), kExact);
  }
}

TEST(Cpca, FewerVectorsDropExactlyTheSmallestVariances) {
  // With M − 1 vectors each cluster loses its smallest eigenvalue s_{k,M−1}²·n/2, with none it
  // loses all of them; the relative error is that over Σ‖x‖². The data's float rounding
  // (~60·6e-8 absolute per component) shifts the scatter by a relative ~1e-5 at most: 1e-4.
  constexpr double kRelative = 1e-4;
  const Synthetic data = makeSynthetic();
  const double total = sumOfSquares(data.vectors);
  double smallest = 0, all = 0;
  for (int k = 0; k < kClusters; ++k)
    for (int d = 0; d < kRank; ++d) {
      const double eigenvalue =
          std::pow(data.spread[std::size_t(k * kRank + d)], 2) * kPerCluster / 2;
      all += eigenvalue;
      if (d == kRank - 1) smallest += eigenvalue;
    }
  const double dropped_one = cpcaRelativeError(
      data.vectors, compressCpca(data.vectors, kDimension, kClusters, kRank - 1, 9));
  EXPECT_GT(dropped_one, 0.0);
  EXPECT_NEAR(dropped_one, smallest / total, kRelative * smallest / total);
  const double dropped_all =
      cpcaRelativeError(data.vectors, compressCpca(data.vectors, kDimension, kClusters, 0, 9));
  EXPECT_NEAR(dropped_all, all / total, kRelative * all / total);
  // A full basis reconstructs anything, here with a single cluster.
  EXPECT_LT(
      cpcaRelativeError(data.vectors, compressCpca(data.vectors, kDimension, 1, kDimension, 9)),
      1e-12);
}

TEST(Cpca, SameSeedSameResult) {
  const Synthetic data = makeSynthetic();
  const CpcaResult a = compressCpca(data.vectors, kDimension, 6, 2, 42);
  const CpcaResult b = compressCpca(data.vectors, kDimension, 6, 2, 42);
  EXPECT_EQ(a.cluster, b.cluster);
  EXPECT_EQ(a.means, b.means);
  EXPECT_EQ(a.bases, b.bases);
  EXPECT_EQ(a.weights, b.weights);
}

void expectRefused(std::span<const float> vectors, int dimension, int clusters, int pca,
                   const std::string& word) {
  try {
    compressCpca(vectors, dimension, clusters, pca, 1);
    ADD_FAILURE() << "expected InputError mentioning " << word;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
  }
}

TEST(Cpca, BadParametersAreRefused) {
  const std::vector<float> six(6, 1.0f);  // three vectors of dimension 2
  expectRefused(six, 2, 0, 1, "clusters");
  expectRefused(six, 2, 4, 1, "clusters");
  expectRefused(six, 2, 1, -1, "pca_vectors");
  expectRefused(six, 2, 1, 3, "pca_vectors");
  expectRefused(six, 0, 1, 0, "dimension");
  expectRefused(six, 4, 1, 0, "dimension");
  expectRefused({}, 2, 1, 0, "dimension");
  std::vector<float> bad = six;
  bad[3] = std::nanf("");
  expectRefused(bad, 2, 1, 0, "finite");
}

}  // namespace
}  // namespace gib::rt::prt
