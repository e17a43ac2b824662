#pragma once
// Grading a class in shares: `raylab grade --shard K/N` grades every N-th
// student starting at K (of the sorted student folders), so that N jobs of
// a cluster's array (examples/slurm/grade_array.sh) split a class; `raylab
// grade --merge OUT SHARD_DIR...` puts the shares together into the report
// an unsharded run writes (the same scores and files; only timings differ).
#include "grade_options.h"

#include <string>
#include <vector>

namespace raylab {

struct Shard {
    int index = 0;  // K
    int count = 1;  // N; 1: the whole class
};

// "K/N" with 0 <= K < N <= 10000. Throws Error.
Shard parseShard(const std::string& text);

// Whether the student at INDEX of the sorted folders belongs to SHARD.
inline bool inShard(std::size_t index, const Shard& shard) {
    return int(index % std::size_t(shard.count)) == shard.index;
}

// `raylab grade --merge OUT SHARD_DIR...`: ARGS is OUT then the shares'
// folders; OPTIONS gives the course's workflow (course file, roster, times,
// LMS). Every share must be there exactly once, from one run; then OUT gets
// the report an unsharded run writes. Throws Error before writing anything
// when the shares do not fit together.
void mergeShards(const std::vector<std::string>& args, const GradeOptions& options);

}  // namespace raylab
