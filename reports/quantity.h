// Quantities: how a suite's [[paper]] values and [[chart]] axes name one number of a job, so that
// the paper's figures and ours are looked up by the same words.
//
//   relmse, ssim, flip_mean, …   a metric value against the reference of the job's path class
//   full:relmse                  the same against the full (all paths) reference
//   frame, <pass name or path>   median milliseconds per measured frame (the frame, one pass)
//   iteration, iteration/<pass>  median milliseconds per iteration of an iterative technique
//   iterations                   the number of iterations run
//   statistic:<name>             a count the technique reports (vertices, atlas_texels, …)
//   parameter:<name>             a technique parameter (numeric for an axis, any for a series)
//   scene                        the job's scene (a series only: it has no number)
//   a + b + …                    the sum of several (a paper's row that spans passes)
#pragma once

#include "reports/results.h"

#include <optional>
#include <string>

namespace gib::reports {

// The number, or nullopt when the job does not have it (a reference job has no frame time, a
// non-numeric parameter has no number).
std::optional<double> quantityValue(const JobResult& job, const std::string& quantity);

// The value as text, for grouping a chart's points into series: a parameter's canonical value,
// else the number as the report prints it; nullopt as for quantityValue.
std::optional<std::string> quantityText(const JobResult& job, const std::string& quantity);

// An axis label: "relMSE against the full reference", "ms per iteration (selection)", …
std::string quantityLabel(const std::string& quantity);

// Whether `quantity` is well formed: a known prefix with a name, or a bare name. The reason when
// not, for a suite file's error.
std::optional<std::string> quantitySyntaxError(const std::string& quantity);

}  // namespace gib::reports
