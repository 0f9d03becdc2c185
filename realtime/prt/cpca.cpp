#include "realtime/prt/cpca.h"

#include "common/input_error.h"
#include "common/splitmix.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace gib::rt::prt {

namespace {

// Lloyd's iterations stop when no vector changes cluster; this only bounds a pathological run
// (each iteration lowers the K-means energy, so it ends, but the bound keeps the time finite).
constexpr int kMaxLloydIterations = 200;
// Jacobi stops when the off-diagonal mass is this fraction of the matrix's squared norm: each
// off-diagonal entry is then below 1e-13 of the norm, so eigenvalues and eigenvectors (for gaps
// above 1e-8 of the norm) are exact far beyond the ~1e-5 the reconstruction needs; the sweep
// bound only guards against a non-converging input (Jacobi converges quadratically).
constexpr double kJacobiOffDiagonal = 1e-26;
constexpr int kMaxJacobiSweeps = 100;

void validate(std::span<const float> vectors, int dimension, int clusters, int pca_vectors) {
  if (dimension < 1)
    throw InputError(fmt::format(
        "CPCA dimension must be at least 1, not {}; pass the length of one transfer vector",
        dimension));
  if (vectors.empty() || vectors.size() % std::size_t(dimension) != 0)
    throw InputError(
        fmt::format("CPCA input holds {} values, not a whole number of vectors of dimension {}; "
                    "pass N × dimension values, N ≥ 1",
                    vectors.size(), dimension));
  const std::size_t count = vectors.size() / std::size_t(dimension);
  if (clusters < 1)
    throw InputError(
        fmt::format("CPCA clusters must be at least 1, not {}; ask for 1 or more", clusters));
  if (std::size_t(clusters) > count)
    throw InputError(fmt::format(
        "CPCA asks for {} clusters of {} vectors; ask for at most as many clusters as vectors",
        clusters, count));
  if (pca_vectors < 0 || pca_vectors > dimension)
    throw InputError(fmt::format(
        "CPCA pca_vectors must be 0 to the dimension {}, not {}; ask for fewer basis vectors",
        dimension, pca_vectors));
  for (std::size_t i = 0; i < vectors.size(); ++i)
    if (!std::isfinite(vectors[i]))
      throw InputError(fmt::format(
          "CPCA input value {} of vector {} (component {}) is not finite; transfer vectors must "
          "be finite",
          vectors[i], i / std::size_t(dimension), i % std::size_t(dimension)));
}

// The i-th uniform double in [0, 1) of the SplitMix64 stream of `seed`.
double uniform(std::uint64_t seed, std::uint64_t i) {
  return double(splitMix64(seed + i * kGoldenGamma) >> 11) * 0x1.0p-53;
}

double squaredDistance(const float* x, const double* centre, int dimension) {
  double sum = 0;
  for (int d = 0; d < dimension; ++d) {
    const double difference = double(x[d]) - centre[d];
    sum += difference * difference;
  }
  return sum;
}

class KMeans {
 public:
  KMeans(std::span<const float> vectors, int dimension, int clusters)
      : x_(vectors),
        dimension_(dimension),
        clusters_(clusters),
        count_(vectors.size() / std::size_t(dimension)),
        centres_(std::size_t(clusters) * std::size_t(dimension)),
        assignment_(count_, -1),
        distance_(count_) {}

  // k-means++: the first centre uniform over the vectors, each next one drawn with probability
  // proportional to the squared distance to the nearest centre chosen so far.
  void seed(std::uint64_t seed) {
    std::uint64_t draw = 0;
    std::vector<double> nearest(count_, std::numeric_limits<double>::infinity());
    auto chosen = std::min(std::size_t(uniform(seed, draw++) * double(count_)), count_ - 1);
    for (int k = 0;; ++k) {
      setCentre(k, chosen);
      if (k + 1 == clusters_) break;
      double total = 0;
      for (std::size_t i = 0; i < count_; ++i) {
        nearest[i] = std::min(nearest[i], squaredDistance(vector(i), centre(k), dimension_));
        total += nearest[i];
      }
      if (total == 0) {  // every vector on a centre: duplicates, any choice is as good
        chosen = std::min(std::size_t(uniform(seed, draw++) * double(count_)), count_ - 1);
        continue;
      }
      const double target = uniform(seed, draw++) * total;
      double cumulative = 0;
      for (std::size_t i = 0; i < count_; ++i) {
        if (nearest[i] == 0) continue;
        chosen = i;
        cumulative += nearest[i];
        if (cumulative > target) break;
      }
    }
  }

  // Lloyd's iterations: assign each vector to its nearest centre (the lowest index on a tie),
  // move each centre to its vectors' mean, until no assignment changes.
  void iterate() {
    for (int iteration = 0; iteration < kMaxLloydIterations; ++iteration) {
      if (!assign()) break;
      updateCentres();
    }
  }

  std::vector<std::int32_t> assignment() const { return assignment_; }

 private:
  const float* vector(std::size_t i) const { return x_.data() + i * std::size_t(dimension_); }
  double* centre(int k) { return centres_.data() + std::size_t(k) * std::size_t(dimension_); }
  void setCentre(int k, std::size_t i) { std::copy(vector(i), vector(i) + dimension_, centre(k)); }

  bool assign() {
    bool changed = false;
    for (std::size_t i = 0; i < count_; ++i) {
      int best = 0;
      double best_distance = std::numeric_limits<double>::infinity();
      for (int k = 0; k < clusters_; ++k) {
        const double d = squaredDistance(vector(i), centre(k), dimension_);
        if (d < best_distance) {
          best_distance = d;
          best = k;
        }
      }
      changed |= assignment_[i] != best;
      assignment_[i] = best;
      distance_[i] = best_distance;
    }
    return changed;
  }

  void updateCentres() {
    std::vector<std::size_t> members(std::size_t(clusters_), 0);
    std::fill(centres_.begin(), centres_.end(), 0.0);
    for (std::size_t i = 0; i < count_; ++i) {
      const int k = assignment_[i];
      ++members[std::size_t(k)];
      for (int d = 0; d < dimension_; ++d) centre(k)[d] += double(vector(i)[d]);
    }
    for (int k = 0; k < clusters_; ++k) {
      if (members[std::size_t(k)] > 0) {
        for (int d = 0; d < dimension_; ++d) centre(k)[d] /= double(members[std::size_t(k)]);
        continue;
      }
      // An empty cluster restarts on the vector farthest from its centre among clusters that
      // keep at least one other vector (the first such on a tie); the next assignment moves it.
      std::size_t farthest = count_;
      for (std::size_t i = 0; i < count_; ++i)
        if (members[std::size_t(assignment_[i])] > 1 &&
            (farthest == count_ || distance_[i] > distance_[farthest]))
          farthest = i;
      if (farthest == count_) continue;  // fewer distinct places than clusters
      --members[std::size_t(assignment_[farthest])];
      ++members[std::size_t(k)];
      distance_[farthest] = 0;
      setCentre(k, farthest);
    }
  }

  std::span<const float> x_;
  int dimension_, clusters_;
  std::size_t count_;
  std::vector<double> centres_;
  std::vector<std::int32_t> assignment_;
  std::vector<double> distance_;
};

// The eigen-decomposition of a symmetric n×n matrix (row-major, destroyed) by cyclic Jacobi
// rotations (Jacobi 1846; the rotation formulas as in Golub & Van Loan §8.5): eigenvalues
// into `values`, eigenvector j as column j of `vectors` (row-major, orthonormal).
void jacobiEigen(std::vector<double>& a, int n, std::vector<double>& values,
                 std::vector<double>& vectors) {
  const auto N = std::size_t(n);
  auto at = [&](std::vector<double>& m, int r, int c) -> double& {
    return m[std::size_t(r) * N + std::size_t(c)];
  };
  vectors.assign(N * N, 0.0);
  for (int i = 0; i < n; ++i) at(vectors, i, i) = 1;
  double norm = 0;
  for (double v : a) norm += v * v;
  for (int sweep = 0; sweep < kMaxJacobiSweeps; ++sweep) {
    double off = 0;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) off += at(a, p, q) * at(a, p, q);
    if (off <= kJacobiOffDiagonal * norm) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        const double apq = at(a, p, q);
        if (apq == 0) continue;
        // The rotation that zeroes a_pq: tan of its angle the smaller root of t² + 2θt − 1 = 0.
        const double theta = (at(a, q, q) - at(a, p, p)) / (2 * apq);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        at(a, p, p) -= t * apq;
        at(a, q, q) += t * apq;
        at(a, p, q) = at(a, q, p) = 0;
        for (int r = 0; r < n; ++r) {
          if (r == p || r == q) continue;
          const double arp = at(a, r, p), arq = at(a, r, q);
          at(a, r, p) = at(a, p, r) = c * arp - s * arq;
          at(a, r, q) = at(a, q, r) = s * arp + c * arq;
        }
        for (int r = 0; r < n; ++r) {
          const double vrp = at(vectors, r, p), vrq = at(vectors, r, q);
          at(vectors, r, p) = c * vrp - s * vrq;
          at(vectors, r, q) = s * vrp + c * vrq;
        }
      }
  }
  values.resize(N);
  for (int i = 0; i < n; ++i) values[std::size_t(i)] = at(a, i, i);
}

// Cluster k's mean and top-M basis into the result, from its members.
void analyseCluster(std::span<const float> x, const std::vector<std::size_t>& members, int k,
                    CpcaResult& result) {
  const int n = result.dimension, m_count = result.pca_vectors;
  const auto N = std::size_t(n);
  float* mean_out = result.means.data() + std::size_t(k) * N;
  float* basis_out = result.bases.data() + std::size_t(k) * std::size_t(m_count) * N;
  if (members.empty()) {  // only with duplicate inputs: any orthonormal basis, a zero mean
    for (int d = 0; d < m_count; ++d) basis_out[std::size_t(d) * N + std::size_t(d)] = 1;
    return;
  }
  // Step 1: the mean.
  std::vector<double> mean(N, 0.0);
  for (std::size_t i : members)
    for (std::size_t d = 0; d < N; ++d) mean[d] += double(x[i * N + d]);
  for (double& v : mean) v /= double(members.size());
  for (std::size_t d = 0; d < N; ++d) mean_out[d] = float(mean[d]);
  if (m_count == 0) return;
  // Step 2: the scatter matrix Σ (x − mean)(x − mean)ᵀ, upper triangle then mirrored.
  std::vector<double> scatter(N * N, 0.0), centred(N);
  for (std::size_t i : members) {
    for (std::size_t d = 0; d < N; ++d) centred[d] = double(x[i * N + d]) - mean[d];
    for (std::size_t r = 0; r < N; ++r) {
      const double cr = centred[r];
      double* row = scatter.data() + r * N;
      for (std::size_t c = r; c < N; ++c) row[c] += cr * centred[c];
    }
  }
  for (std::size_t r = 0; r < N; ++r)
    for (std::size_t c = 0; c < r; ++c) scatter[r * N + c] = scatter[c * N + r];
  // Step 3: its eigenvectors by decreasing eigenvalue (the lower index on a tie), each signed
  // so that its largest-magnitude component is positive: a deterministic choice of ±.
  std::vector<double> values, vectors;
  jacobiEigen(scatter, n, values, vectors);
  std::vector<int> order(N);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return values[std::size_t(a)] > values[std::size_t(b)]; });
  for (int d = 0; d < m_count; ++d) {
    const auto column = std::size_t(order[std::size_t(d)]);
    std::size_t largest = 0;
    for (std::size_t r = 1; r < N; ++r)
      if (std::abs(vectors[r * N + column]) > std::abs(vectors[largest * N + column])) largest = r;
    const double sign = vectors[largest * N + column] < 0 ? -1.0 : 1.0;
    for (std::size_t r = 0; r < N; ++r)
      basis_out[std::size_t(d) * N + r] = float(sign * vectors[r * N + column]);
  }
}

}  // namespace

CpcaResult compressCpca(std::span<const float> vectors, int dimension, int clusters,
                        int pca_vectors, std::uint64_t seed) {
  validate(vectors, dimension, clusters, pca_vectors);
  const auto N = std::size_t(dimension), M = std::size_t(pca_vectors);
  const std::size_t count = vectors.size() / N;

  // Step 1: K-means.
  KMeans k_means(vectors, dimension, clusters);
  k_means.seed(seed);
  k_means.iterate();

  CpcaResult result;
  result.dimension = dimension;
  result.pca_vectors = pca_vectors;
  result.clusters = clusters;
  result.cluster = k_means.assignment();
  result.means.assign(std::size_t(clusters) * N, 0.0f);
  result.bases.assign(std::size_t(clusters) * M * N, 0.0f);
  result.weights.assign(count * M, 0.0f);

  // Step 2: per cluster, its mean and principal directions.
  std::vector<std::vector<std::size_t>> members(static_cast<std::size_t>(clusters));
  for (std::size_t i = 0; i < count; ++i) members[std::size_t(result.cluster[i])].push_back(i);
  for (int k = 0; k < clusters; ++k) analyseCluster(vectors, members[std::size_t(k)], k, result);

  // Step 3: each vector's weights, its offset from the stored mean projected on the stored
  // basis (the least-squares weights for the basis as rounded to float).
  for (std::size_t i = 0; i < count; ++i) {
    const auto k = std::size_t(result.cluster[i]);
    const float* mean = result.means.data() + k * N;
    for (std::size_t d = 0; d < M; ++d) {
      const float* basis = result.bases.data() + (k * M + d) * N;
      double w = 0;
      for (std::size_t c = 0; c < N; ++c)
        w += (double(vectors[i * N + c]) - double(mean[c])) * double(basis[c]);
      result.weights[i * M + d] = float(w);
    }
  }
  return result;
}

namespace {

// x̂ of vector i in double.
void reconstructDouble(const CpcaResult& result, std::size_t i, double* out) {
  const auto N = std::size_t(result.dimension), M = std::size_t(result.pca_vectors);
  const auto k = std::size_t(result.cluster[i]);
  for (std::size_t c = 0; c < N; ++c) out[c] = double(result.means[k * N + c]);
  for (std::size_t d = 0; d < M; ++d) {
    const double w = double(result.weights[i * M + d]);
    const float* basis = result.bases.data() + (k * M + d) * N;
    for (std::size_t c = 0; c < N; ++c) out[c] += w * double(basis[c]);
  }
}

}  // namespace

void reconstructVector(const CpcaResult& result, std::size_t index, std::span<float> out) {
  if (index >= result.vectorCount() || out.size() < std::size_t(result.dimension))
    throw std::invalid_argument("reconstructVector: no such vector or too short an output");
  std::vector<double> x(std::size_t(result.dimension));
  reconstructDouble(result, index, x.data());
  for (std::size_t c = 0; c < x.size(); ++c) out[c] = float(x[c]);
}

std::vector<float> reconstruct(const CpcaResult& result) {
  const auto N = std::size_t(result.dimension);
  std::vector<float> out(result.vectorCount() * N);
  for (std::size_t i = 0; i < result.vectorCount(); ++i)
    reconstructVector(result, i, std::span<float>(out).subspan(i * N, N));
  return out;
}

double cpcaRelativeError(std::span<const float> vectors, const CpcaResult& result) {
  const auto N = std::size_t(result.dimension);
  if (vectors.size() != result.vectorCount() * N)
    throw std::invalid_argument("cpcaRelativeError: the vectors are not the ones compressed");
  std::vector<double> x(N);
  double error = 0, total = 0;
  for (std::size_t i = 0; i < result.vectorCount(); ++i) {
    reconstructDouble(result, i, x.data());
    for (std::size_t c = 0; c < N; ++c) {
      const double v = double(vectors[i * N + c]);
      error += (v - x[c]) * (v - x[c]);
      total += v * v;
    }
  }
  return total > 0 ? error / total : error;
}

}  // namespace gib::rt::prt
