// Writes a reference render as gibench outputs: a float32 EXR with layers (mean as RGB,
// "variance", "direct", "indirect") and gibench/* metadata, a PNG for looking at, and checkpoint
// EXRs of the mean for convergence plots.
#pragma once

#include "image/exr_io.h"
#include "reference/progressive_renderer.h"
#include "scene/scene.h"

#include <filesystem>

namespace gib::ref {

// Metadata of docs/architecture.md ("Images"): program version, scene and its hash, technique,
// parameters, samples, seed, bounce limits, Embree version.
image::Metadata referenceMetadata(const scene::Scene& scene, const RenderSettings& settings);

// Degrees of freedom of the variance layer of a reference EXR, from its gibench/replicas
// metadata (replicas − 1); 0 when it has none.
std::uint32_t varianceDegreesOfFreedom(const image::Metadata& metadata);

// The keys that describe how a run went rather than what it computed: the only ones that differ
// between two runs of the same command.
inline constexpr const char* kRunDependentKeys[] = {
    "gibench/render_seconds", "gibench/rays_per_second", "gibench/peak_rss_mb"};

// Render time, rays per second and the process's peak resident memory so far.
void addRunMetadata(image::Metadata& metadata, const RenderResult& result);

// Peak resident set size of this process, in MiB.
double peakResidentMegabytes();

// Writes `exr_path` and, beside it, the PNG (same stem) through the OCIO display transform.
// Returns the PNG's path.
std::filesystem::path writeReferenceOutputs(const std::filesystem::path& exr_path,
                                            const RenderResult& result,
                                            const image::Metadata& metadata);

// "<dir>/<stem>.spp0004.exr" for a checkpoint after 4 samples per pixel.
std::filesystem::path checkpointPath(const std::filesystem::path& exr_path, std::uint32_t spp);

// Throws InputError when the file cannot be created where asked (missing directory, not
// writable, not .exr), before any rendering time is spent.
void checkOutputPath(const std::filesystem::path& exr_path);

}  // namespace gib::ref
