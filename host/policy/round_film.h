// Adaptive sampling's image, unbiased. Samples come in rounds; a round's per-pixel counts are decided from earlier
// rounds only, so each round's pixel mean is unbiased given them. Rounds are then combined with per-pixel weights
// fixed before the round's samples were seen (roundWeight: the pixel's samples this round over those it has left,
// as planned then), which sum to 1 over a render that ends where it planned to:
//   estimate_p = sum_r w_{r,p} mean_{r,p} / sum_r w_{r,p}.
// The plain sample mean over all rounds would weigh a round by counts chosen from that round's own values (through
// the later rounds' allocations): the classic trap (a pixel that looked dark early gets fewer samples later, so
// its early low values weigh more), biased. Each replicate of a pixel is combined the same way, so the replicate
// spread is still its variance (QMC samplers); the independent sampler's variance is
// sum_r w_{r,p}^2 s_{r,p}^2 / n_{r,p} from each round's own sample variance.
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "render/film.h"

namespace vkmc {

// A pixel's weight for its next round of `samples`, from the weight it has had, the samples it is planned to get
// after this round (its share of this round times the render's samples still to come) and whether this round is
// planned to be the render's last. With counts that never change, the weights are each round's share of the
// pixel's samples: the plain mean.
double roundWeight(double weightSoFar, double samples, double laterSamples, bool last);

class RoundFilm {
 public:
  RoundFilm(uint32_t width, uint32_t height, uint32_t replicates, bool replicateVariance);
  // A finished round: its samples alone (a film of that round's batches) and each pixel's weight, fixed before
  // it rendered (roundWeight).
  void addRound(const Film& round, const std::vector<double>& weight);
  uint32_t rounds() const { return rounds_; }
  // The weight a pixel has had so far (1 once its planned last round is in).
  double weightSoFar(size_t pixel) const { return weight_[pixel]; }
  // The combined estimate as a Film whose mean() and varianceOfMean() read it (their sums are set to match; the
  // counts are the samples taken), for the outputs and the report.
  Film image() const;
  // Per pixel, the combined mean and one sample's variance (pooled within rounds): what the allocation reads.
  std::vector<glm::dvec3> means() const;
  std::vector<glm::dvec3> sampleVariances() const;
  std::vector<double> costs() const;  // a sample's mean camera-path vertices (Film::cost)

 private:
  uint32_t width_, height_, replicates_;
  bool replicateVariance_;
  uint32_t rounds_ = 0;
  std::vector<double> weight_;        // per pixel: sum_r w_{r,p}
  std::vector<double> replicateSum_;  // per pixel and replicate, 3 each: sum_r w_r * the replicate's round mean
  std::vector<double> varianceSum_;   // per pixel, 3: sum_r w_r^2 s_r^2 / n_r (independent samples)
  std::vector<double> squares_;       // per pixel, 3: sums of squared deviations from each round's mean
  std::vector<uint64_t> squaresDof_;  // per pixel: their degrees of freedom, sum_r (n_r - 1)
  std::vector<uint64_t> replicateCount_;
  std::vector<uint64_t> count_, nonfinite_, highRange_;
  std::vector<double> vertices_;
};

}  // namespace vkmc
