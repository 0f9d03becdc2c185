// [[figure]] of a suite file: a source document's figure rebuilt from the suite's jobs, their
// pictures in a grid (results::FigureSpec). The report gives each figure a page and a composite
// PNG (reports/figure_page.h, reports/figure_composite.h).
//
//   [[figure]]
//   name = "fig6"                       # a slug (letters, digits, '-', '_'), unique in the suite
//   title = "Fig. 6: the radiosity map after 1, 4 and 50 iterations"
//   caption = "…"                       # optional
//   columns = 3                         # optional: cells per row; default the number of panels
//
//   [[figure.panel]]                    # one or more, in reading order
//   job = "iterations-1"                # a job id of this suite
//   image = "aux:atlas"                 # image, reference, difference, flip or aux:<name>
//   caption = "1 iteration"             # optional
//   row = 1                             # optional, 1-based: place the panel explicitly
//   column = 1                          #   (default: the next free cell, rows filled in order)
//   metric = "relmse"                   # optional: the number under the picture, a quantity
//                                       # (results/quantity.h) or "none"; default the run's
//                                       # primary metric
//
// Panels placed by both row and column take their cells first, then those given only a row (the
// first free column of that row) or only a column (the first free row of that column), then the
// rest fill the free cells row by row. An auxiliary image's name is not checked here: a technique
// reports its auxiliary images when it runs.
#pragma once

#include "common/toml_reader.h"
#include "results/results.h"
#include "suites/job_expansion.h"

#include <vector>

namespace gib::suites {

// Every problem (an unknown job id or image kind, two panels in one cell, a figure name used
// twice, a column beyond `columns`, flip of a job that does not measure flip, a malformed metric)
// throws gib::InputError with one positioned line naming the figure, the problem and the fix.
std::vector<results::FigureSpec> readFigures(const TomlTableReader& root,
                                             const std::vector<Job>& jobs);

}  // namespace gib::suites
