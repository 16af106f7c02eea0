#include "reinforce_growth_schedule.h"

#include "reinforce_regrowth_policy.h"
#include "reinforce_round_records.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace reinforce {

using namespace regrowth_policy;

Growth::Growth(HostHooks &host, Zone &zone, SoftRelaxation &relax, const std::vector<Seed> &seeds)
    : host_(host), zone_(zone), relax_(relax)
{
  for (const Seed &s : seeds) seed_of_[s.id] = &s;
}

GrowthOutcome Growth::run(double start)
{
  outcome_ = GrowthOutcome{};
  started_ = said_ = host_.wall_time();
  for (int stage = 1; stage <= kStages; ++stage) {
    const double scale = stage == kStages ? 1.0 : start + (1 - start) * stage / kStages;
    relax_.set_scale(scale);
    outcome_.scale = scale;
    if (scale < kPullUntil) {
      relax_.set_pull(kPull);
      relax_.run(kPullSteps, -1);    // every step, overlaps or not
      relax_.set_pull(0);
    }
    // What is left above kAbort with no seed near it is not a jam yet: the
    // matrix may still settle in the stages after (a stage's few hundred
    // steps are not a verdict; measured: a jam called here gave up scenes
    // that grew back whole when let on).
    drop_until(relax_.run(kStageSteps, kStageSettled), kAbort, kStageSteps);
    char where[80];
    std::snprintf(where, sizeof where, "stage %d of %d (radii %.3f of their own)", stage, kStages,
                  scale);
    progress(where);
  }
  double worst = relax_.run(kJudgeSteps, kNearlyJammed);
  worst = drop_until(worst, kNearlyJammed, kJudgeSteps);
  outcome_.jammed = worst > kNearlyJammed;
  progress("grown; the exact end");
  bool clear = !outcome_.jammed && finish();
  for (int k = 0; k < kDrops && !clear && !outcome_.jammed; ++k)
    clear = drop_overlapped(0) && finish();
  outcome_.clear = clear;
  return outcome_;
}

// A line on the log once the growth has run kProgressEvery seconds, and at
// most that often: where it is, the steps and the time so far (rank 0's
// clock; not collective).
void Growth::progress(const char *where)
{
  const double now = host_.wall_time();
  if (now - said_ < kProgressEvery) return;
  said_ = now;
  char line[300];
  std::snprintf(line, sizeof line,
                "fix reinforce/invert: regrowth: %s, %lld FIRE steps, %lld seeds given up, %.1f s\n",
                where, static_cast<long long>(relax_.steps()),
                static_cast<long long>(outcome_.given_up), now - started_);
  host_.log(line);
}

// While the largest overlap `worst` exceeds `above`: half of the growing
// seeds above it given up together, then at most `steps` FIRE steps; at
// most kDrops rounds, and once no seed is above it only one more
// relaxation (what is left is the matrix's own). Returns the largest
// overlap left.
double Growth::drop_until(double worst, double above, int steps)
{
  bool longer = false;    // relaxed once more with no seed above it
  for (int k = 0; k < kDrops && worst > above; ++k) {
    if (!drop_overlapped(above)) {
      if (longer) break;
      longer = true;
    }
    worst = relax_.run(steps, above);
  }
  return worst;
}

// Half of the growing seeds whose deepest overlap exceeds `above` (at
// least one), the deepest first, equal ones by id: every process gathers
// them and gives up the same. True when one was.
bool Growth::drop_overlapped(double above)
{
  std::vector<double> mine;
  for (int k : zone_.moving) {
    const ZoneBody &b = zone_.bodies[static_cast<std::size_t>(k)];
    if (!b.growing || !b.present) continue;
    const double d = relax_.deepest(k);
    if (!(d > above)) continue;
    put_id(b.id, mine);
    mine.push_back(d);
  }
  const std::vector<double> all = host_.gather_all(mine);
  std::vector<std::pair<double, std::int64_t>> order;
  for (std::size_t k = 0; k + 3 <= all.size(); k += 3) {
    std::int64_t id = 0;
    if (!read_id(&all[k], id)) host_.fail("Fix reinforce/invert: internal error: bad seed id");
    order.push_back({-all[k + 2], id});
  }
  if (order.empty()) return false;
  std::sort(order.begin(), order.end());
  order.resize((order.size() + 1) / 2);
  std::vector<std::int64_t> ids;
  for (const auto &o : order) ids.push_back(o.second);
  give_up(ids);
  return true;
}

// A seed given up leaves the zone (deleted at the end); one placed shrunk
// by the relocation stays, at its shrunk radius, a sphere of the packing.
void Growth::give_up(const std::vector<std::int64_t> &ids)
{
  for (std::int64_t id : ids) {
    const Seed &seed = *seed_of_.at(id);
    for (int k : zone_.copies_of(id)) {
      ZoneBody &b = zone_.bodies[static_cast<std::size_t>(k)];
      b.growing = false;
      if (seed.r > 0) {
        b.R = seed.r;
        b.packing = true;
      } else {
        b.present = false;
      }
    }
  }
  outcome_.given_up += static_cast<std::int64_t>(ids.size());
  relax_.flags_changed();
}

// The exact end: FIRE with every pair of movable spheres' contact padded
// by kPad of the smaller radius until no padded overlap exceeds half of
// it, then at the true radii until none exceeds kClear; true when no pair
// overlaps beyond kClear of its smaller radius (beyond what it overlapped
// at the start), every process's.
bool Growth::finish()
{
  relax_.set_pad(kPad);
  relax_.run(kFinishSteps, 0.5 * kPad);
  relax_.set_pad(0);
  relax_.run(kFinishSteps, kClear);
  std::int64_t above = 0;
  relax_.worst_at_full_size(kClear, above);
  return host_.sum(static_cast<double>(above)) == 0;
}

void Growth::undo(const std::vector<Seed> &seeds)
{
  std::vector<std::int64_t> ids;
  for (const Seed &s : seeds) {
    const std::vector<int> copies = zone_.copies_of(s.id);
    if (!copies.empty() && zone_.bodies[static_cast<std::size_t>(copies.front())].growing)
      ids.push_back(s.id);
  }
  give_up(ids);
  for (std::size_t k = 0; k < zone_.bodies.size(); ++k) zone_.x[k] = zone_.bodies[k].x0;
}

}    // namespace reinforce
