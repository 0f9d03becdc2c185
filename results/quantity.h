// Quantities: how a suite's [[paper]] values and [[chart]] axes name one number of a job, so that
// the paper's figures and ours are looked up by the same words.
//
//   relmse, ssim, flip_mean, …   a metric value against the reference of the job's path class
//   full:relmse                  the same against the full (all paths) reference
//   frame, <pass name or path>   median milliseconds per measured frame (the frame, one pass)
//   iteration, iteration/<pass>  median milliseconds per iteration of an iterative technique
//   iterations                   the number of iterations run
//   statistic:<name>             a count the technique reports (vertices, atlas_texels, …)
//   parameter:<name>             a technique parameter (numeric for an axis, any for a series);
//                                parameter:scene.<name> a scene parameter
//   scene                        the job's scene (a series only: it has no number)
//   a + b + …                    the sum of several (a paper's row that spans passes)
//
// Pass names are the technique's declared passes (realtime/pass_declarations.h); a suite is
// checked against them when it loads (quantityPasses).
#pragma once

#include "results/results.h"

#include <optional>
#include <string>
#include <vector>

namespace gib::results {

// The number, or nullopt when the job does not have it (a reference job has no frame time, a
// non-numeric parameter has no number).
std::optional<double> quantityValue(const JobResult& job, const std::string& quantity);

// An axis label: "relMSE against the full reference", "ms per iteration (selection)", …
std::string quantityLabel(const std::string& quantity);

// Whether `quantity` is well formed: a known prefix with a name, or a bare name. The reason when
// not, for a suite file's error.
std::optional<std::string> quantitySyntaxError(const std::string& quantity);

// The terms of a well-formed quantity that name pass timings ("shadow map",
// "frame/lights/shadow map", "iteration", "iteration/update"), in order; empty when it names
// none (a metric, a statistic, a parameter).
std::vector<std::string> quantityPasses(const std::string& quantity);

// The statistics a well-formed quantity names ("vertices" of "statistic:vertices"), in order; a
// suite is checked against the techniques' declared statistics when it loads.
std::vector<std::string> quantityStatistics(const std::string& quantity);

// The job's parameter of that name ("scene.<name>": its scene's), as its canonical text; nullopt
// when it has none.
std::optional<std::string> parameterText(const JobResult& job, std::string_view name);

inline constexpr std::string_view kParameterPrefix = "parameter:";

}  // namespace gib::results
