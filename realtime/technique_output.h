// A technique's frame as a gibench output: the float EXR with the gibench/* metadata (scene,
// technique and parameters, path class, GL identity, frames and timing facts) and a PNG beside
// it. Shared by `gibench render` and the harness's runner.
#pragma once

#include "common/parameters.h"
#include "image/exr_io.h"
#include "realtime/technique.h"
#include "realtime/technique_runner.h"
#include "scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gib::rt {

// The parameters as one JSON object {"key": "canonical value", …}.
std::string parametersJson(const ParameterValues& values);

image::Metadata techniqueOutputMetadata(const scene::Scene& scene, const TechniqueInfo& info,
                                        const ParameterValues& parameters,
                                        const TechniqueRunSettings& settings,
                                        const TechniqueRunResult& result, double frame_ms_median);

struct AuxiliaryImageFiles {
  std::string name, description;
  std::filesystem::path exr, png;
};

struct TechniqueOutputFiles {
  std::filesystem::path png;
  std::vector<AuxiliaryImageFiles> auxiliary;
};

// Writes `exr_path` and the PNG of the same stem beside it, and each auxiliary image as
// "<stem>-<name>.exr" and ".png" with the same metadata.
TechniqueOutputFiles writeTechniqueOutputs(const std::filesystem::path& exr_path,
                                           const TechniqueRunResult& result,
                                           const image::Metadata& metadata);

}  // namespace gib::rt
