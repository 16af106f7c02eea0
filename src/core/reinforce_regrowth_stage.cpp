#include "reinforce_regrowth_stage.h"

#include "reinforce_cell_grid.h"

#include <algorithm>
#include <array>
#include <map>

namespace reinforce {

RegrowthStage::RegrowthStage(const Settings &settings, const Domain &domain,
                             const BlockLattice &lattice, double width, double matrix_rmax,
                             double largest_r, RegrowthStats &stats)
    : settings_(settings), domain_(domain), lattice_(lattice), width_(width),
      read_(regrowth_reach(width, matrix_rmax, largest_r).read), stats_(stats)
{
}

StageResult RegrowthStage::run(const std::vector<Particle> &reads,
                               const std::function<bool(const Particle &)> &mine)
{
  // The seeds by block: each block's zone is regrown on its own, so what a
  // process runs together does not change the result.
  std::map<std::array<int, 3>, std::vector<std::size_t>> blocks;
  for (std::size_t k = 0; k < reads.size(); ++k) {
    if (reads[k].role != Role::Target || !mine(reads[k])) continue;
    std::array<int, 3> b;
    lattice_.block_of(reads[k].x, b.data());
    blocks[b].push_back(k);
  }
  StageResult result;
  if (blocks.empty()) return result;
  CellGrid grid(read_);
  for (std::size_t k = 0; k < reads.size(); ++k) grid.insert(reads[k].x, static_cast<int>(k));
  std::vector<Particle> near;
  std::vector<int> picked;
  for (const auto &block : blocks) {
    // The particles within reach of the block's seeds, the seeds first.
    picked.clear();
    for (std::size_t s : block.second)
      grid.for_each_near(reads[s].x, read_, [&](int k) {
        if (norm(reads[static_cast<std::size_t>(k)].x - reads[s].x) <= read_) picked.push_back(k);
      });
    std::sort(picked.begin(), picked.end());
    picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
    near.clear();
    std::vector<std::size_t> seeds;
    for (int k : picked) {
      if (std::binary_search(block.second.begin(), block.second.end(), static_cast<std::size_t>(k)))
        seeds.push_back(near.size());
      near.push_back(reads[static_cast<std::size_t>(k)]);
    }
    std::vector<RoundRecord> records = regrow(near, seeds, width_, settings_, domain_, stats_);
    result.records.insert(result.records.end(), records.begin(), records.end());
    result.done += block.second.size();
  }
  return result;
}

}    // namespace reinforce
