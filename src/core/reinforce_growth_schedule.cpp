#include "reinforce_growth_schedule.h"

#include "reinforce_regrowth_policy.h"
#include "reinforce_round_records.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace reinforce {

using namespace regrowth_policy;

Growth::Growth(HostHooks &host, Zone &zone, SoftRelaxation &relax, const std::vector<Seed> &seeds)
    : host_(host), zone_(zone), relax_(relax)
{
  for (const Seed &s : seeds) seed_of_[s.id] = &s;
}

static double envd(const char *n, double d) { const char *v = getenv(n); return v ? atof(v) : d; }
GrowthOutcome Growth::run(double start)
{
  outcome_ = GrowthOutcome{};
  bool jammed = false;
  const int kStages = (int)envd("RG_STAGES", regrowth_policy::kStages);
  const double geom = envd("RG_GEOM", 0);
  const int kPullSteps = (int)envd("RG_PULLSTEPS", regrowth_policy::kPullSteps);
  const int kStageSteps = (int)envd("RG_STAGESTEPS", regrowth_policy::kStageSteps);
  if (envd("RG_CONT", 0) > 0) {
    relax_.set_scale(start);
    relax_.set_pull(kPull);
    relax_.set_growth(envd("RG_RATE", 1e-3), 1.0, envd("RG_TAU", 1e-2), kPullUntil);
    double worst = relax_.run((int)envd("RG_MAXSTEPS", 3000), kNearlyJammed);
    if (getenv("RDEBUG")) fprintf(stderr, "cont steps %ld scale %.4f worst %.2e\n", (long)relax_.steps(), relax_.scale(), worst);
    int rounds = 0;
    while ((worst > kNearlyJammed || relax_.scale() < 1) && rounds++ < kDrops) {
      if (!drop_overlapped(kNearlyJammed)) break;
      worst = relax_.run((int)envd("RG_DROPSTEPS", 500), kNearlyJammed);
      if (getenv("RDEBUG")) fprintf(stderr, "drop steps %ld scale %.4f worst %.2e given %ld\n", (long)relax_.steps(), relax_.scale(), worst, (long)outcome_.given_up);
    }
    relax_.set_growth(0, 0, 0, 0);
    outcome_.scale = relax_.scale();
    jammed = worst > kNearlyJammed || relax_.scale() < 1;
    bool clear = !jammed && finish();
    if (getenv("RDEBUG")) fprintf(stderr, "finish steps %ld clear %d\n", (long)relax_.steps(), clear);
    for (int k = 0; k < kDrops && !clear && !jammed; ++k)
      clear = drop_overlapped(0) && finish();
    outcome_.clear = clear;
    outcome_.jammed = jammed;
    return outcome_;
  }
  for (int stage = 1; stage <= kStages && !jammed; ++stage) {
    bool last = stage == kStages;
    double scale = last ? 1.0 : start + (1 - start) * stage / kStages;
    if (geom > 0) { scale = 1 - (1 - start) * std::pow(geom, stage); if (1 - scale < 2e-3) { scale = 1; last = true; } }
    relax_.set_scale(scale);
    outcome_.scale = scale;
    if (scale < kPullUntil) {
      relax_.set_pull(kPull);
      relax_.run(kPullSteps, -1);    // every step, overlaps or not
      relax_.set_pull(0);
    }
    const auto before = relax_.steps();
    double worst = relax_.run(kStageSteps, kStageSettled);
    const auto mid = relax_.steps();
    worst = drop_until(worst, kAbort, kStageSteps);
    jammed = worst > kAbort;
    if (last) stage = kStages;
    if (jammed && getenv("RDEBUG")) {
      for (int k : zone_.moving) {
        const double d = relax_.deepest(k);
        if (d > kAbort) { const ZoneBody &b = zone_.bodies[k]; fprintf(stderr, "  body id %ld R %.4g growing %d packing %d deepest %.3g off %.3g cap %.3g\n", (long)b.id, b.R, b.growing, b.packing, d, norm(zone_.x[k]-b.x0), b.cap);
          for (std::size_t j = 0; j < zone_.bodies.size(); ++j) { const ZoneBody &o = zone_.bodies[j]; if ((int)j==k || !o.present) continue; double rj = o.movable ? relax_.scale()*o.R : o.R; double ov = (relax_.scale()*b.R + rj - norm(zone_.x[k]-zone_.x[j]))/std::min(relax_.scale()*b.R, rj); if (ov > 0.01) fprintf(stderr, "     with id %ld R %.4g rebar %d movable %d growing %d ov %.3g off %.3g\n", (long)o.id, o.R, o.rebar, o.movable, o.growing, ov, norm(zone_.x[j]-o.x0)); } }
      }
    }
    if (getenv("RDEBUG")) fprintf(stderr, "stage %d scale %.3f steps %ld + drops %ld worst %.2e given %ld\n", stage, scale, (long)(mid-before), (long)(relax_.steps()-mid), worst, (long)outcome_.given_up);
  }
  if (!jammed) {
    auto before = relax_.steps();
    double worst = relax_.run(kJudgeSteps, kNearlyJammed);
    worst = drop_until(worst, kNearlyJammed, kJudgeSteps);
    jammed = worst > kNearlyJammed;
    if (getenv("RDEBUG")) fprintf(stderr, "judge steps %ld worst %.2e given %ld\n", (long)(relax_.steps()-before), worst, (long)outcome_.given_up);
    before = relax_.steps();
    bool clear = !jammed && finish();
    if (getenv("RDEBUG")) fprintf(stderr, "finish steps %ld clear %d\n", (long)(relax_.steps()-before), clear);
    for (int k = 0; k < kDrops && !clear && !jammed; ++k)
      clear = drop_overlapped(0) && finish();
    outcome_.clear = clear;
  }
  outcome_.jammed = jammed;
  return outcome_;
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
