#include "perception/leg_competition.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace shelfdock::perception {
namespace {

bool Share(const std::array<int, 4>& a, const std::array<int, 4>& b) {
  for (int i : a) {
    if (i >= 0 && std::find(b.begin(), b.end(), i) != b.end()) return true;
  }
  return false;
}

// Depth-first include/exclude over hypotheses sorted by weight, pruned when the chosen weight
// plus every weight still to decide cannot beat the best found.
class Search {
 public:
  Search(const std::vector<std::vector<char>>& conflict, const std::vector<double>& weight,
         int max_nodes)
      : conflict_(conflict), weight_(weight), max_nodes_(max_nodes) {
    suffix_.assign(weight.size() + 1, 0.0);
    for (std::size_t i = weight.size(); i-- > 0;) suffix_[i] = suffix_[i + 1] + weight[i];
  }

  std::vector<int> Run() {
    Visit(0, 0.0);
    return best_;
  }
  bool complete() const { return nodes_ <= max_nodes_; }

 private:
  void Visit(std::size_t i, double total) {
    if (++nodes_ > max_nodes_) return;
    if (total + suffix_[i] <= best_total_) return;
    if (i == weight_.size()) {
      best_total_ = total;
      best_ = chosen_;
      return;
    }
    const bool free =
        std::none_of(chosen_.begin(), chosen_.end(), [&](int c) { return conflict_[i][c] != 0; });
    if (free) {
      chosen_.push_back(static_cast<int>(i));
      Visit(i + 1, total + weight_[i]);
      chosen_.pop_back();
    }
    Visit(i + 1, total);
  }

  const std::vector<std::vector<char>>& conflict_;
  const std::vector<double>& weight_;
  int max_nodes_;
  int nodes_ = 0;
  std::vector<double> suffix_;
  std::vector<int> chosen_;
  std::vector<int> best_;
  double best_total_ = -1.0;
};

}  // namespace

std::vector<int> SelectDisjoint(const std::vector<std::array<int, 4>>& legs,
                                const std::vector<double>& weights,
                                const std::vector<std::vector<char>>& also_exclusive,
                                int max_nodes) {
  const std::size_t n = legs.size();
  if (weights.size() != n) {
    throw std::invalid_argument("SelectDisjoint: " + std::to_string(weights.size()) +
                                " weights for " + std::to_string(n) + " hypotheses");
  }
  if (!also_exclusive.empty() &&
      (also_exclusive.size() != n ||
       std::any_of(also_exclusive.begin(), also_exclusive.end(),
                   [n](const std::vector<char>& row) { return row.size() != n; }))) {
    throw std::invalid_argument("SelectDisjoint: also_exclusive must be empty or " +
                                std::to_string(n) + " x " + std::to_string(n));
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return weights[a] > weights[b]; });
  std::vector<double> w(n);
  std::vector<std::vector<char>> conflict(n, std::vector<char>(n, 0));
  for (std::size_t i = 0; i < n; ++i) {
    w[i] = weights[order[i]];
    for (std::size_t j = 0; j < i; ++j) {
      const bool exclusive = !also_exclusive.empty() && also_exclusive[order[i]][order[j]] != 0;
      conflict[i][j] = conflict[j][i] = exclusive || Share(legs[order[i]], legs[order[j]]) ? 1 : 0;
    }
  }
  Search search(conflict, w, max_nodes);
  std::vector<int> picked = search.Run();
  if (!search.complete()) {
    // Too many overlapping hypotheses for the exact search: greedy by weight.
    picked.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if (std::none_of(picked.begin(), picked.end(), [&](int c) { return conflict[i][c]; })) {
        picked.push_back(static_cast<int>(i));
      }
    }
  }
  std::vector<int> out;
  for (int p : picked) out.push_back(order[p]);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace shelfdock::perception
