#pragma once

#include <array>
#include <vector>

namespace shelfdock::perception {

/// Hypotheses compete for legs: a leg cluster belongs to at most one returned shelf. Given each
/// hypothesis' leg clusters (-1 for none) and its weight (> 0), returns the indices of the
/// disjoint subset with the largest total weight, in input order. A phantom made of two
/// neighbours' legs thus loses to the two real shelves it borrows from (their weights add up).
/// Exact (branch and bound, best weight first) up to `max_nodes` search nodes, then greedy by
/// weight for the rest: scans have a handful of competing hypotheses.
/// `also_exclusive` (empty, or n x n) marks pairs that exclude each other for another reason
/// (two footprints that overlap: two shelves cannot stand in one place).
/// Throws std::invalid_argument when `weights` or `also_exclusive` do not match `legs`.
std::vector<int> SelectDisjoint(const std::vector<std::array<int, 4>>& legs,
                                const std::vector<double>& weights,
                                const std::vector<std::vector<char>>& also_exclusive = {},
                                int max_nodes = 20000);

}  // namespace shelfdock::perception
