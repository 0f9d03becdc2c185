// The references a job is measured against (suites/job_execution.h): a technique job whose image
// is an obscurance has that obscurance's reference alone, the one its Slurm reference task
// renders too.
#include "suites/job_execution.h"

#include <gtest/gtest.h>

namespace gib::suites {
namespace {

Job directJob() {
  Job job;
  job.suite = "s";
  job.case_name = "c";
  job.id = "c";
  job.slug = "c";
  job.scene.name = "cornell";
  job.technique = "direct";
  job.settings.width = 16;
  job.settings.height = 12;
  job.settings.reference.spp = 8;
  job.settings.reference.seed = 3;
  return job;
}

TEST(JobReferences, RadianceJobHasItsClassAndTheFullReference) {
  const Job job = directJob();
  const PreparedJob p = prepareJob(job);
  EXPECT_FALSE(p.obscurance);
  const std::vector<ref::ReferenceSpec> specs = jobReferences(p);
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[0].path_class, p.path_class);
  EXPECT_EQ(specs[1].path_class, scene::PathClass{});
  for (const ref::ReferenceSpec& spec : specs) EXPECT_FALSE(spec.obscurance);
}

// `environment_occlusion = false` in a case's reference: its class's reference lights diffuse and
// glossy surfaces by the unblocked environment, the full one keeps the occlusion; a job whose
// class is every path then still has both.
TEST(JobReferences, EnvironmentWithoutOcclusionKeepsAnOccludedFullReference) {
  Job job = directJob();
  job.settings.reference.environment_occlusion = false;
  const PreparedJob p = prepareJob(job);
  std::vector<ref::ReferenceSpec> specs = jobReferences(p);
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_FALSE(specs[0].environment_occlusion);
  EXPECT_EQ(specs[1].path_class, scene::PathClass{});
  EXPECT_TRUE(specs[1].environment_occlusion);
  PreparedJob every_path = p;
  every_path.path_class = scene::PathClass{};
  specs = jobReferences(every_path);
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[0].path_class, specs[1].path_class);
  EXPECT_NE(specs[0].environment_occlusion, specs[1].environment_occlusion);
}

// A suite's lens reaches the job's scene (its hash, so the store key) and the references' specs
// (entry.json, so that store verification renders the same lens); a pinhole job keeps its key.
TEST(JobReferences, TheLensReachesTheSceneAndTheSpecs) {
  const Job pinhole_job = directJob();
  Job job = pinhole_job;
  job.settings.lens.radius = 10.0;
  job.settings.lens.focus_distance = 900.0;
  const PreparedJob pinhole = prepareJob(pinhole_job);
  const PreparedJob lens = prepareJob(job);
  EXPECT_EQ(lens.scene.camera.lens_radius, 10.0f);
  EXPECT_EQ(lens.scene.camera.focus_distance, 900.0f);
  EXPECT_NE(lens.scene_hash, pinhole.scene_hash);
  const std::vector<ref::ReferenceSpec> specs = jobReferences(lens);
  ASSERT_EQ(specs.size(), 2u);
  for (const ref::ReferenceSpec& spec : specs) EXPECT_EQ(spec.lens, job.settings.lens);
  EXPECT_NE(ref::referenceKey(lens.scene, specs[0]),
            ref::referenceKey(pinhole.scene, jobReferences(pinhole)[0]));
  Job zero = pinhole_job;
  zero.settings.lens.radius = 0.0;
  EXPECT_EQ(prepareJob(zero).scene_hash, pinhole.scene_hash);
}

TEST(JobReferences, ObscuranceJobHasItsObscuranceReferenceAlone) {
  const Job job = directJob();
  PreparedJob p = prepareJob(job);
  // As prepareJob records it for a technique whose imageObscurance() is set.
  const scene::ObscuranceDefinition definition{scene::ObscuranceFalloff::kAmbientOcclusion,
                                               scene::ObscuranceMode::kSpectral, 0.2f};
  p.obscurance = definition;
  const std::vector<ref::ReferenceSpec> specs = jobReferences(p);
  ASSERT_EQ(specs.size(), 1u);
  EXPECT_EQ(specs[0].obscurance, definition);
  // Every path, whatever the technique's class: the key is the obscurance's alone.
  EXPECT_EQ(specs[0].path_class, scene::PathClass{});
  EXPECT_EQ(specs[0].pixel_sampling, ref::PixelSampling::kCenter);
  EXPECT_EQ(specs[0].spp, 8u);
  EXPECT_EQ(specs[0].seed, 3u);
  EXPECT_EQ(specs[0].width, 16);
  EXPECT_EQ(describeJob(p).path_class, scene::describeObscurance(definition));
}

}  // namespace
}  // namespace gib::suites
