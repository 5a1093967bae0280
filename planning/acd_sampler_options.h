#pragma once
// Options of the ACD-guided samplers (dissertation Ch. VI.C, Algorithm 10).

#include <cstdint>
#include <string>

namespace acdplan::planning {

/// How AcdValidStateSampler / AcdStateSampler orient a rigid robot (SE(2), SE(3)).
enum class AcdOrientation {
  kRandom,   ///< Uniformly random orientation (Algorithm 10).
  kAligned,  ///< Near an opening: the robot's long axis across the opening (perpendicular to
             ///< the opening segment), either way round, plus Gaussian jitter. Elsewhere random.
};

/// "random" or "aligned". @throws InputError otherwise.
AcdOrientation ParseAcdOrientation(const std::string& name);
std::string ToString(AcdOrientation orientation);

/// Options of the ACD samplers; `{}` is valid.
///
/// A sample is drawn as follows: with probability `uniform_share` uniformly from the whole
/// state space (this keeps the sampler probabilistically complete); otherwise a target is
/// picked at random with probability proportional to its weight -- a component's centroid has
/// weight 1, an opening's midpoint `opening_weight` * (mean opening length / its length),
/// capped at `max_narrowness` * `opening_weight` -- and the robot's reference point is drawn
/// from an isotropic Gaussian around it: sigma = `centroid_spread` * sqrt(component area) for
/// a centroid, `opening_spread` * opening length for an opening.
struct AcdSamplerOptions {
  double uniform_share = 0.1;    ///< Share of plain uniform samples; in [0, 1].
  double opening_weight = 4.0;   ///< Weight of an opening of mean length vs. a centroid; >= 0.
  double max_narrowness = 10.0;  ///< Cap on (mean opening length / length); >= 1.
  double centroid_spread = 0.3;  ///< Gaussian sigma / sqrt(component area); > 0.
  double opening_spread = 0.5;   ///< Gaussian sigma / opening length; > 0.
  AcdOrientation orientation = AcdOrientation::kRandom;
  double long_axis = 0.0;        ///< kAligned: body-frame angle of the robot's long axis [rad].
  double aligned_jitter = 0.15;  ///< kAligned: sigma of the yaw around the aligned yaw [rad]; >= 0.
  int max_attempts = 100;        ///< Valid sampler: candidates tried per sample() call; >= 1.
  std::uint64_t seed = 1;        ///< Seed of the first sampler; later ones get derived seeds.
};

/// @throws InputError naming the field and the rule if an option is out of range.
void CheckAcdSamplerOptions(const AcdSamplerOptions& options);

}  // namespace acdplan::planning
