// The pictures a measured job leaves for the report, in the files suites/job_directory.h names:
// the reference for looking at and its full-precision copy, the error maps, the thumbnail and the
// viewer's linear data.
#pragma once

#include "image/image.h"
#include "metrics/metric_registry.h"
#include "reference/reference_store.h"
#include "results/results.h"
#include "suites/job_directory.h"

#include <string>

namespace gib::suites {

// Writes reference.png (a copy of the store's, so that the run directory stands alone),
// difference.png and flip.png of `test` against `reference` (`report` holds the FLIP map when
// flip was measured; no error maps when `test` is empty, a reference job without checkpoints), the
// thumbnail and the viewer's data, and records them in `outputs`.
void writeComparisonImages(const JobDirectory& files, const ref::StoredReference& reference,
                           const image::Image& test, const metrics::MetricReport& report,
                           results::JobOutputs& outputs);

// The run's full-precision copy of the stored reference's EXR (mean, variance, direct and indirect
// layers), made by the first job that needs it. Returns its path as the results record it.
std::string copyReferenceExr(const JobDirectory& files, const ref::StoredReference& reference);

}  // namespace gib::suites
