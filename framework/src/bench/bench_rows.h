#pragma once
// Helpers over bench rows shared by the bench writers of this folder
// (bench_csv.cpp, bench_markdown.cpp, bench_plot.cpp). Not for use elsewhere.
#include "bench_report.h"

#include <string>
#include <utility>
#include <vector>

namespace raylab::bench {

// Measured: a value the Pareto front and the plot can use.
bool measured(const BenchRow& r);

// The scenes in order of first appearance, each with its rows' indices.
std::vector<std::pair<std::string, std::vector<std::size_t>>>
byScene(const std::vector<BenchRow>& rows);

// INDICES sorted by frame time (stable: equal times keep their order; rows
// without a time go last).
void sortByFrameTime(std::vector<std::size_t>& indices, const std::vector<BenchRow>& rows);

// Control characters (a newline in a scene name) would break a line-based
// format; they become spaces.
std::string oneLine(const std::string& s);
}  // namespace raylab::bench
