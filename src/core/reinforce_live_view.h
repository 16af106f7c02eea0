// A process's view as the rounds of the schedule change it, and which
// rounds read each of its particles (docs/design.md, "What a round reads").
#pragma once

#include "reinforce_cell_grid.h"
#include "reinforce_domain.h"
#include "reinforce_particle.h"
#include "reinforce_round_records.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace reinforce {

// The rounds whose targets (those this process relocates) lie within
// `reach` of each view particle, one bit per round: a round's relocation
// then starts from the particles with its bit, about a tenth of the view,
// instead of testing the whole view every round. The reach is what
// relocate_targets would use on the whole view, so the particles it keeps
// are among them.
class RoundsNear {
public:
  explicit RoundsNear(double reach) : reach_(reach), grid_(reach * (1 + 1e-9)) {}
  void add_target(Vec3 x, int round)
  {
    grid_.insert_around(x, static_cast<int>(targets_.size()));
    targets_.push_back({x, round});
  }
  std::uint64_t of(const Particle &p) const
  {
    std::uint64_t bits = 0;
    grid_.for_each_in_cell(p.x, [&](int t) {
      if (norm(targets_[t].x - p.x) <= reach_) bits |= std::uint64_t{1} << targets_[t].round;
    });
    return bits;
  }

private:
  struct Target {
    Vec3 x;
    int round;
  };
  double reach_;
  CellGrid grid_;
  std::vector<Target> targets_;
};

// The view as the rounds change it, as the host would give it after
// migrating the atoms and rebuilding the ghosts: a moved atom's copies are
// replaced by its wrapped centre and the periodic images of it inside this
// process's view; a deleted one's copies go; a kept one becomes present.
// Particles never move in the vector (an atom's old copies are marked gone,
// its new ones appended), so the index by ID, sorted once, stays valid and
// a round's records cost what they hold, not a pass over the view.
class LiveView {
public:
  LiveView(std::vector<Particle> view, const RoundsNear &rounds_near)
      : view_(std::move(view)), gone_(view_.size(), false), rounds_near_(rounds_near)
  {
    near_.reserve(view_.size());
    by_id_.reserve(view_.size());
    for (std::size_t k = 0; k < view_.size(); ++k) {
      near_.push_back(rounds_near_.of(view_[k]));
      by_id_.emplace_back(view_[k].id, k);
    }
    std::sort(by_id_.begin(), by_id_.end());
  }

  // The particles round `round` reads (those near its targets), in view order.
  void read_by(int round, std::vector<Particle> &out) const
  {
    out.clear();
    for (std::size_t k = 0; k < view_.size(); ++k)
      if (near_[k] >> round & 1) out.push_back(view_[k]);
  }

  void apply(const std::vector<RoundRecord> &records, const Domain &domain)
  {
    std::vector<std::size_t> copies;
    for (const RoundRecord &rec : records) {
      const std::int64_t id = rec.id;
      const RecordKind what = rec.kind;
      const Vec3 v = rec.v;
      copies_of(id, copies);
      // A push moves the present sphere only; a vacant copy of the same
      // atom (a target the regrowth takes up again) stays where it is.
      if (what == RecordKind::Pushed || what == RecordKind::Moved)
        copies.erase(std::remove_if(copies.begin(), copies.end(),
                                    [&](std::size_t c) { return view_[c].role == Role::Target; }),
                     copies.end());
      if (what == RecordKind::Kept) {
        for (std::size_t c : copies) view_[c].role = Role::Matrix;
        continue;
      }
      if (copies.empty() && what != RecordKind::Placed)
        continue;    // neither seen nor to be seen here
      Particle moved;
      if (!copies.empty()) moved = view_[copies.front()];
      // The in-box copy, if this process has it, is where a push starts.
      for (std::size_t c : copies)
        if (in_box(view_[c].x, domain)) moved = view_[c];
      for (std::size_t c : copies) {
        gone_[c] = true;
        near_[c] = 0;
      }
      if (what == RecordKind::Deleted) continue;
      if (what == RecordKind::Placed) {
        moved.id = id;
        moved.x = v;
        moved.r = rec.r;
        moved.role = Role::Matrix;
        moved.pushable = true;    // a target is a matrix atom of the fix group
        if (copies.empty()) moved.owned = false;
      } else if (what == RecordKind::Moved) {
        moved.x = v;
      } else {
        moved.x = moved.x + v;
      }
      for (const Vec3 &image : images_in_view(wrapped_into_box(moved.x, domain), domain, true)) {
        Particle p = moved;
        p.x = image;
        p.owned = false;
        added_[id].push_back(view_.size());
        view_.push_back(p);
        near_.push_back(rounds_near_.of(p));
        gone_.push_back(false);
      }
    }
  }

private:
  // The present copies of atom `id`.
  void copies_of(std::int64_t id, std::vector<std::size_t> &out) const
  {
    out.clear();
    const auto first =
        std::lower_bound(by_id_.begin(), by_id_.end(), std::pair<std::int64_t, std::size_t>{id, 0});
    for (auto it = first; it != by_id_.end() && it->first == id; ++it)
      if (!gone_[it->second]) out.push_back(it->second);
    const auto more = added_.find(id);
    if (more == added_.end()) return;
    for (std::size_t c : more->second)
      if (!gone_[c]) out.push_back(c);
  }

  std::vector<Particle> view_;
  std::vector<std::uint64_t> near_;    // rounds near each particle (none once gone)
  std::vector<bool> gone_;
  std::vector<std::pair<std::int64_t, std::size_t>> by_id_;             // the first view, by id
  std::unordered_map<std::int64_t, std::vector<std::size_t>> added_;    // later copies
  const RoundsNear &rounds_near_;
};

}    // namespace reinforce
