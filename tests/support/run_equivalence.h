// Whether two runs of one suite agree on everything that does not depend on where, when or how
// fast they ran: the job set and order, and per job its definition, reference keys, metrics and
// convergence series. What a run assembled from shards or Slurm tasks must share with a local one.
#pragma once

#include "results/results.h"

#include <gtest/gtest.h>

namespace gib::test {

// gtest assertions, one per differing field, naming the job.
void expectSameDeterministicResults(const results::RunResults& local,
                                    const results::RunResults& assembled);

}  // namespace gib::test
