#include <polyplan/arm/arm_grid_search.hpp>

#include <polyplan/arm/arm_motion.hpp>
#include <polyplan/arm/detail/outward_rounding.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace polyplan {

namespace {

constexpr std::uint32_t unreached = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint8_t no_parent = 0xff;
constexpr std::size_t max_joints = 12;

// A cell's flags: its state (ArmCellState) in the low two bits, and whether this run closed it.
constexpr std::uint8_t state_mask = 3, closed_bit = 4;

// The longest turn a move of one step makes, as a real number: cells k and k + 1 sit at the
// doubles nearest k·step and (k + 1)·step, each within half an ulp of 2π (2^-51) of those, and
// the move across 0 turns 2π − (n − 1)·step, where n·step lies within 2^-53·2π of two_pi and
// two_pi within 2^-51 of 2π. So no move turns more than step + 2^-49 (rounded up).
double longest_move(double step) { return detail::above(step + 0x1p-49); }

// A move between two free cells whose safe angles along its joint are a and b units: free when
// the two ends' free stretches, [from, from + a) and (to − b, to], cover it — a + b > 255 units,
// which exceed the longest move. (An end that alone reaches the other, 255, still needs the
// other's clearance above 0, b ≥ 1: contact at the far end is not free.)
bool stretches_cover(std::uint8_t a, std::uint8_t b) { return int{a} + int{b} > 255; }

}  // namespace

std::uint8_t safe_angle_units(double safe, double unit) {
  const double units = std::floor(detail::below(safe / unit));  // safe / unit rounded down, then its whole part
  return units >= 255 ? 255 : units <= 0 ? 0 : static_cast<std::uint8_t>(units);
}

struct ArmGridSearch::Impl {
  using Coordinates = std::array<std::int32_t, max_joints>;

  // ~4096 neighbouring cells (a cube of side 2^side_bits on every axis), allocated when the search
  // first touches one of them. Structure of arrays: the search reads g and flags far more often.
  struct Block {
    std::vector<std::uint32_t> g;      // steps from the start, this run
    std::vector<std::uint8_t> flags;   // state and closed
    std::vector<std::uint8_t> parent;  // 2·axis + (1 when the move increased it), this run
    std::vector<std::uint8_t> safe;    // [cell · joints + j]: quantized safe angles, once measured
  };

  const ArmCollisionChecker* checker;
  JointSafeAngles safe_angles;
  ArmGridSearchProblem problem;
  std::size_t joints;
  std::int64_t n;
  double step;
  double move;  // longest_move(step): what a safe angle must reach to cover a move alone
  double unit;  // of the stored safe angles: move / 255, rounded up
  int side_bits;
  std::int64_t blocks_per_axis;
  std::size_t cells_per_block;
  std::vector<std::unique_ptr<Block>> blocks;
  std::unordered_map<std::uint64_t, std::uint32_t> block_index;
  std::size_t block_bytes;
  // Buckets of the open list by f in steps; within a bucket the last pushed is taken first, which
  // follows the newest, deepest branch through the plateaus of equal f that a sum-of-joints
  // metric has everywhere.
  std::vector<std::vector<std::uint64_t>> buckets;
  std::size_t queue_bytes = 0;
  // Scratch.
  JointAngles configuration_a, configuration_b;
  std::vector<double> safe_scratch;
  // The problem's goals as the search reads them (the heuristic runs for every cell pushed and
  // popped): fixed-size coordinates, and their ids, in the problem's order.
  std::vector<Coordinates> goal_cells;
  std::vector<std::uint64_t> goal_ids;
  std::uint64_t cached_key = ~std::uint64_t{0};
  Block* cached_block = nullptr;
  ArmGridSearchResult result;

  Impl(const ArmCollisionChecker& c, ArmGridSearchProblem p)
      : checker(&c), safe_angles(c), problem(std::move(p)), joints(c.arm().joints()), n(problem.cells_per_axis) {
    if (joints > max_joints)
      throw std::invalid_argument("ArmGridSearch: at most " + std::to_string(max_joints) + " joints");
    if (n < 3) throw std::invalid_argument("ArmGridSearch: at least 3 cells per axis");
    // Cells are numbered in 64 bits.
    if (static_cast<double>(joints) * std::log2(static_cast<double>(n)) >= 63)
      throw std::invalid_argument("ArmGridSearch: " + std::to_string(n) + "^" + std::to_string(joints) +
                                  " cells cannot be numbered in 63 bits");
    if (problem.goals.empty()) throw std::invalid_argument("ArmGridSearch: no goal cell");
    require_cell(problem.start);
    for (const auto& goal : problem.goals) require_cell(goal);
    step = two_pi / static_cast<double>(n);
    move = longest_move(step);
    unit = detail::above(move / 255);
    side_bits = std::max(1, 12 / static_cast<int>(joints));
    while (side_bits > 1 && (std::int64_t{1} << (side_bits - 1)) >= n)
      --side_bits;  // no block much wider than the grid
    blocks_per_axis = (n + (std::int64_t{1} << side_bits) - 1) >> side_bits;
    cells_per_block = std::size_t{1} << (side_bits * static_cast<int>(joints));
    block_bytes = cells_per_block * (sizeof(std::uint32_t) + 2 + joints) + sizeof(Block) + 64;
    configuration_a.resize(joints);
    configuration_b.resize(joints);
    safe_scratch.resize(joints);
    for (const auto& goal : problem.goals) {
      Coordinates g{};
      std::copy(goal.begin(), goal.end(), g.begin());
      goal_cells.push_back(g);
      goal_ids.push_back(id(g));
    }
  }

  void require_cell(const std::vector<std::int32_t>& cell) const {
    if (cell.size() != joints)
      throw std::invalid_argument("ArmGridSearch: " + std::to_string(cell.size()) + " coordinates for " +
                                  std::to_string(joints) + " joints");
    for (const std::int32_t x : cell)
      if (x < 0 || x >= n)
        throw std::invalid_argument("ArmGridSearch: coordinate " + std::to_string(x) + " outside [0, n)");
  }

  std::size_t bytes() const { return blocks.size() * block_bytes + block_index.size() * 32 + queue_bytes; }

  std::uint64_t id(const Coordinates& x) const {
    std::uint64_t c = 0;
    for (std::size_t i = joints; i-- > 0;) c = c * static_cast<std::uint64_t>(n) + static_cast<std::uint64_t>(x[i]);
    return c;
  }
  void decode(std::uint64_t c, Coordinates& x) const {
    for (std::size_t i = 0; i < joints; ++i) {
      x[i] = static_cast<std::int32_t>(c % static_cast<std::uint64_t>(n));
      c /= static_cast<std::uint64_t>(n);
    }
  }

  // The block and offset of a cell; allocates the block when `allocate`, else may return null.
  Block* locate(const Coordinates& x, std::size_t& offset, bool allocate) {
    std::uint64_t key = 0;
    offset = 0;
    const std::int32_t mask = (std::int32_t{1} << side_bits) - 1;
    for (std::size_t i = joints; i-- > 0;) {
      key = key * static_cast<std::uint64_t>(blocks_per_axis) + static_cast<std::uint64_t>(x[i] >> side_bits);
      offset = (offset << side_bits) | static_cast<std::size_t>(x[i] & mask);
    }
    if (key == cached_key) return cached_block;
    const auto it = block_index.find(key);
    Block* b = nullptr;
    if (it != block_index.end()) {
      b = blocks[it->second].get();
    } else {
      if (!allocate) return nullptr;
      if (!fits(block_bytes)) return nullptr;
      auto fresh = std::make_unique<Block>();
      fresh->g.assign(cells_per_block, unreached);
      fresh->flags.assign(cells_per_block, 0);
      fresh->parent.assign(cells_per_block, no_parent);
      fresh->safe.assign(cells_per_block * joints, 0);
      b = fresh.get();
      block_index.emplace(key, static_cast<std::uint32_t>(blocks.size()));
      blocks.push_back(std::move(fresh));
    }
    cached_key = key;
    cached_block = b;
    return b;
  }

  void configuration(const Coordinates& x, JointAngles& q) const {
    for (std::size_t i = 0; i < joints; ++i) q[i] = static_cast<double>(x[i]) * step;
  }

  // Measures a cell once: its state and its joints' safe angles.
  void evaluate(Block& b, std::size_t offset, const Coordinates& x) {
    configuration(x, configuration_a);
    ++result.cells_evaluated;
    const bool free = safe_angles.measure(configuration_a, move, safe_scratch);
    b.flags[offset] = static_cast<std::uint8_t>(
        (b.flags[offset] & ~state_mask) | static_cast<std::uint8_t>(free ? ArmCellState::free : ArmCellState::blocked));
    if (free)
      for (std::size_t j = 0; j < joints; ++j) b.safe[offset * joints + j] = safe_angle_units(safe_scratch[j], unit);
  }

  std::int64_t heuristic(const Coordinates& x) const {
    if (!problem.use_heuristic) return 0;
    std::int64_t nearest = std::numeric_limits<std::int64_t>::max();
    for (const Coordinates& goal : goal_cells) {
      std::int64_t h = 0;
      for (std::size_t i = 0; i < joints; ++i) {
        std::int64_t d = std::abs(std::int64_t{x[i]} - goal[i]);
        if (problem.torus) d = std::min(d, n - d);
        h += d;
      }
      nearest = std::min(nearest, h);
    }
    return nearest;
  }

  // False, pushing nothing, when the bucket would grow beyond the budget.
  bool push(std::uint64_t cell, std::int64_t f) {
    const auto k = static_cast<std::size_t>(f);
    if (k >= buckets.size()) buckets.resize(k + 1);
    auto& bucket = buckets[k];
    if (bucket.size() == bucket.capacity()) {
      const std::size_t grown = std::max<std::size_t>(64, 2 * bucket.capacity());
      const std::size_t more = (grown - bucket.capacity()) * sizeof(std::uint64_t);
      if (!fits(more)) return false;
      queue_bytes += more;
      bucket.reserve(grown);
    }
    bucket.push_back(cell);
    return true;
  }

  void begin_run() {
    for (auto& b : blocks) {
      std::fill(b->g.begin(), b->g.end(), unreached);
      std::fill(b->parent.begin(), b->parent.end(), no_parent);
      for (auto& f : b->flags) f &= state_mask;
    }
    for (auto& bucket : buckets) std::vector<std::uint64_t>().swap(bucket);
    buckets.clear();
    queue_bytes = 0;
    const std::size_t kept_cells = result.cells_evaluated, kept_peak = result.peak_bytes;
    result = ArmGridSearchResult{};
    result.cells_evaluated = kept_cells;  // measured cells are counted once across runs
    result.peak_bytes = kept_peak;
  }

  // Whether `more` bytes fit within the budget; when not, the run ends over budget.
  bool fits(std::size_t more) {
    if (bytes() + more <= problem.memory_bytes) {
      result.peak_bytes = std::max(result.peak_bytes, bytes() + more);
      return true;
    }
    result.over_budget = true;
    return false;
  }

  ArmGridSearchResult run() {
    begin_run();
    Coordinates x{}, y{};
    std::copy(problem.start.begin(), problem.start.end(), x.begin());
    std::size_t offset = 0;
    Block* b = locate(x, offset, true);
    if (!b) return finish();
    if ((b->flags[offset] & state_mask) == static_cast<std::uint8_t>(ArmCellState::unknown)) evaluate(*b, offset, x);
    if ((b->flags[offset] & state_mask) != static_cast<std::uint8_t>(ArmCellState::free)) return finish();
    b->g[offset] = 0;
    ++result.generated;
    if (!push(id(x), heuristic(x))) return finish();

    for (std::size_t f = 0; f < buckets.size(); ++f) {
      while (!buckets[f].empty()) {
        const std::uint64_t cell = buckets[f].back();
        buckets[f].pop_back();
        decode(cell, x);
        b = locate(x, offset, false);
        const std::uint32_t g = b->g[offset];
        if ((b->flags[offset] & closed_bit) || g + heuristic(x) != static_cast<std::int64_t>(f)) continue;  // stale
        b->flags[offset] |= closed_bit;
        ++result.expanded;
        if (problem.record_expanded)
          result.expanded_order.emplace_back(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(joints));
        if (const auto reached = std::find(goal_ids.begin(), goal_ids.end(), cell); reached != goal_ids.end()) {
          result.goal_reached = static_cast<std::size_t>(reached - goal_ids.begin());
          trace_path(x);
          return finish();
        }
        std::array<std::uint8_t, max_joints> here_safe;
        std::copy_n(&b->safe[offset * joints], joints, here_safe.begin());
        for (std::size_t i = 0; i < joints; ++i)
          for (const std::int32_t sign : {-1, 1}) {
            y = x;
            y[i] += sign;
            if (y[i] < 0 || y[i] >= n) {
              if (!problem.torus) continue;
              y[i] = y[i] < 0 ? static_cast<std::int32_t>(n - 1) : 0;
            }
            const std::int64_t h = heuristic(y);
            if (problem.in_corridor && !problem.in_corridor(std::span<const std::int32_t>(y.data(), joints))) {
              result.outside_bound_steps = std::min(result.outside_bound_steps, std::int64_t{g} + 1 + h);
              continue;
            }
            std::size_t there = 0;
            Block* nb = locate(y, there, true);
            if (!nb) return finish();  // over the budget
            if ((nb->flags[there] & closed_bit) || nb->g[there] <= g + 1) continue;
            if ((nb->flags[there] & state_mask) == static_cast<std::uint8_t>(ArmCellState::unknown))
              evaluate(*nb, there, y);
            if ((nb->flags[there] & state_mask) != static_cast<std::uint8_t>(ArmCellState::free)) continue;
            if (!move_is_free(x, here_safe[i], y, nb->safe[there * joints + i])) continue;
            if (nb->g[there] == unreached) ++result.generated;
            nb->g[there] = g + 1;
            nb->parent[there] = static_cast<std::uint8_t>(2 * i + (sign > 0 ? 1 : 0));
            if (!push(id(y), std::int64_t{g} + 1 + h)) return finish();
          }
      }
      std::vector<std::uint64_t>().swap(buckets[f]);  // f never comes back: a consistent heuristic
    }
    return finish();
  }

  bool move_is_free(const Coordinates& from, std::uint8_t from_safe, const Coordinates& to, std::uint8_t to_safe) {
    if (stretches_cover(from_safe, to_safe)) {
      ++result.moves_by_clearance;
      return true;
    }
    configuration(from, configuration_a);
    configuration(to, configuration_b);
    ++result.moves_certified;
    const MotionCertificate certificate = certify_motion(*checker, configuration_a, configuration_b);
    result.moves_uncertified += certificate.verdict == MotionCertificate::Verdict::uncertified;
    return certificate.free();
  }

  void trace_path(const Coordinates& goal) {
    Coordinates x = goal;
    std::size_t offset = 0;
    for (;;) {
      result.path.emplace_back(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(joints));
      const Block* b = locate(x, offset, false);
      const std::uint8_t parent = b->parent[offset];
      if (parent == no_parent) break;
      const std::size_t axis = parent / 2;
      x[axis] += (parent & 1) ? -1 : 1;  // undo the move that reached x
      if (x[axis] < 0) x[axis] = static_cast<std::int32_t>(n - 1);
      if (x[axis] >= n) x[axis] = 0;
    }
    std::reverse(result.path.begin(), result.path.end());
    result.found = true;
    result.cost_steps = static_cast<std::int64_t>(result.path.size()) - 1;
  }

  ArmGridSearchResult finish() {
    result.peak_bytes = std::max(result.peak_bytes, bytes());
    return result;
  }
};

ArmGridSearch::ArmGridSearch(const ArmCollisionChecker& checker, ArmGridSearchProblem problem)
    : impl_(std::make_unique<Impl>(checker, std::move(problem))) {}
ArmGridSearch::~ArmGridSearch() = default;

ArmGridSearchResult ArmGridSearch::run() { return impl_->run(); }

void ArmGridSearch::set_corridor(std::function<bool(std::span<const std::int32_t>)> in_corridor) {
  impl_->problem.in_corridor = std::move(in_corridor);
}

ArmCellState ArmGridSearch::state(std::span<const std::int32_t> cell) const {
  Impl::Coordinates x{};
  std::copy(cell.begin(), cell.end(), x.begin());
  std::size_t offset = 0;
  const Impl::Block* b = impl_->locate(x, offset, false);
  return b ? static_cast<ArmCellState>(b->flags[offset] & state_mask) : ArmCellState::unknown;
}

}  // namespace polyplan
