#include "reinforce_round_runner.h"

#include "reinforce_live_view.h"
#include "reinforce_round_records.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <unordered_map>

namespace reinforce {

namespace {

// The owned atoms' part: moves, kept flags, and the atoms to delete (removed
// by the caller after the last round, so local indices stay valid).
void apply_to_host(HostHooks &host, const AtomArrays &a,
                   const std::unordered_map<std::int64_t, int> &owned,
                   const std::vector<RoundRecord> &records, std::vector<int> &doomed)
{
  for (const RoundRecord &rec : records) {
    auto it = owned.find(rec.id);
    if (it == owned.end()) continue;
    const int i = it->second;
    switch (rec.kind) {
    case RecordKind::Placed:
      host.move(i, rec.v, rec.r);
      break;
    case RecordKind::Deleted:
      doomed.push_back(i);
      break;
    case RecordKind::Kept:
      host.set_pending(i, false);
      break;
    case RecordKind::Pushed:
      host.move(i, Vec3{a.x[i][0], a.x[i][1], a.x[i][2]} + rec.v, a.radius[i]);
      break;
    case RecordKind::Moved:
      host.move(i, rec.v, a.radius[i]);
      break;
    }
  }
}

// A block of the lattice in one round: {round, i, j, k}.
using BlockKey = std::array<int, 4>;

BlockKey block_key(const BlockLattice &lattice, int round, Vec3 x)
{
  int b[3];
  lattice.block_of(x, b);
  return {round, b[0], b[1], b[2]};
}

// The blocks (with their rounds) where the other processes have targets,
// sorted: each block's targets are relocated by one process only.
std::vector<BlockKey> others_blocks(HostHooks &host, const std::vector<BlockKey> &mine)
{
  std::vector<double> flat;
  for (const BlockKey &k : mine) flat.insert(flat.end(), k.begin(), k.end());
  const std::vector<double> every = host.gather_all(flat);
  std::vector<BlockKey> others;
  for (std::size_t n = 0; n + 4 <= every.size(); n += 4) {
    const BlockKey k{static_cast<int>(every[n]), static_cast<int>(every[n + 1]),
                     static_cast<int>(every[n + 2]), static_cast<int>(every[n + 3])};
    if (!std::binary_search(mine.begin(), mine.end(), k)) others.push_back(k);
  }
  std::sort(others.begin(), others.end());
  return others;
}

// True when block `key` shares a face, an edge or a corner with one of
// `blocks` in round `round` (across periodic boundaries too).
bool touches(const BlockLattice &lattice, const Domain &box, const BlockKey &key, int round,
             const std::vector<BlockKey> &blocks)
{
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj)
      for (int dk = -1; dk <= 1; ++dk) {
        BlockKey n{round, key[1] + di, key[2] + dj, key[3] + dk};
        bool inside = true;
        for (int d = 0; d < 3; ++d) {
          const int count = lattice.count[d];
          if (n[d + 1] >= 0 && n[d + 1] < count) continue;
          if (!box.periodic[d]) inside = false;
          n[d + 1] = (n[d + 1] + count) % count;
        }
        if (inside && std::binary_search(blocks.begin(), blocks.end(), n)) return true;
      }
  return false;
}

}    // namespace

// One collective instead of one per element.
std::vector<double> reduce_all(HostHooks &host, const std::vector<double> &mine, bool take_max)
{
  const std::vector<double> every = host.gather_all(mine);
  if (mine.empty()) return {};
  std::vector<double> out(mine.size(), take_max ? -INFINITY : 0.0);
  for (std::size_t k = 0; k < every.size(); ++k) {
    double &o = out[k % mine.size()];
    o = take_max ? std::max(o, every[k]) : o + every[k];
  }
  return out;
}

// The processes whose round results this one needs, and which need its
// own: those that can change an atom this one sees. A process relocates
// blocks reaching at most `beyond` past its subdomain and moves atoms at
// most `write` from a target, so it changes nothing farther than
// beyond + write from its subdomain; this process sees atoms within `seen`
// of its own (its view bounds) and owns atoms only inside it. Two
// subdomains closer than beyond + write + seen in every dimension (nearest
// periodic image) are partners, both ways. Ranks in ascending order; this
// process is among them (the host skips itself).
std::vector<int> exchange_partners(HostHooks &host, const Domain &domain, double beyond,
                                   double write, double seen)
{
  const std::vector<double> boxes =
      host.gather_all({domain.sub_lo.x, domain.sub_lo.y, domain.sub_lo.z, domain.sub_hi.x,
                       domain.sub_hi.y, domain.sub_hi.z});
  // A hair wider: a spare partner costs an empty message, a missing one
  // would leave this process's view stale.
  const double apart = (beyond + write + seen) * (1 + 1e-9);
  std::vector<int> partners;
  for (std::size_t p = 0; p + 6 <= boxes.size(); p += 6) {
    bool near = true;
    for (int d = 0; d < 3 && near; ++d) {
      const double lo = boxes[p + d], hi = boxes[p + 3 + d];
      const double period = domain.hi[d] - domain.lo[d];
      double gap = INFINITY;
      for (int shift = -1; shift <= 1; ++shift) {
        if (shift != 0 && !domain.periodic[d]) continue;
        const double s = shift * period;
        gap =
            std::min(gap, std::max({0.0, lo + s - domain.sub_hi[d], domain.sub_lo[d] - (hi + s)}));
      }
      near = gap <= apart;
    }
    if (near) partners.push_back(static_cast<int>(p / 6));
  }
  return partners;
}

namespace {

// The rounds of one stage on one process: which rounds its particles
// belong to, the blocks it runs, its view as the rounds change it, and the
// records it applies to the host's atoms.
class RoundRunner {
public:
  RoundRunner(HostHooks &host, Stage &stage, const RoundPlan &plan, std::vector<Particle> view,
              const std::vector<int> &local, const AtomArrays &a, std::vector<int> &doomed)
      : host_(host), stage_(stage), plan_(plan), a_(a), doomed_(doomed),
        rounds_near_(stage.read_reach())
  {
    for (std::size_t k = 0; k < view.size(); ++k)
      if (view[k].owned) owned_[view[k].id] = local[k];
    per_round_.assign(static_cast<std::size_t>(stage.passes()) * plan.lattice.rounds(), 0.0);
    for (const Particle &p : view) {
      const int round = round_of(p);
      if (round < 0) continue;
      per_round_[round] += 1;
      rounds_near_.add_target(p.x, round);
      my_blocks_.push_back(block_key(plan.lattice, round, p.x));
    }
    per_round_ = reduce_all(host, per_round_, false);
    work_.assign(per_round_.size(), 0.0);
    // Rounds are a bit each in RoundsNear.
    if (per_round_.size() > 64)
      host.fail("Fix reinforce/invert: internal error: more than 64 rounds");
    std::sort(my_blocks_.begin(), my_blocks_.end());
    my_blocks_.erase(std::unique(my_blocks_.begin(), my_blocks_.end()), my_blocks_.end());
    other_blocks_ = others_blocks(host, my_blocks_);
    live_.reset(new LiveView(std::move(view), rounds_near_));
  }

  // In a round, this process first runs its blocks that do not touch
  // (share a face, edge or corner with) another process's block of the
  // round before, then collects that round's results from the others,
  // then runs the rest: a block reads nothing another process changed in a
  // block not touching it (blocks are at least write + read reach wide),
  // so the work waits only where it must, and the results are those of
  // running the rounds one after the other (docs/design.md, "Overlapping
  // the exchange").
  RoundsDone run()
  {
    RoundsDone done;
    const double start = host_.wall_time();
    double said = start;
    int previous = -1;    // the round whose others' results are still to collect
    for (std::size_t round = 0; round < per_round_.size(); ++round) {
      if (per_round_[round] == 0) continue;
      done.rounds++;
      const int r = static_cast<int>(round);
      const double now = host_.wall_time();
      if (done.rounds > 1 && now - said >= kProgressEvery) {
        say_progress(r, done.rounds, now - start);
        said = now;
      }
      const auto first =
          std::lower_bound(my_blocks_.begin(), my_blocks_.end(), BlockKey{r, 0, 0, 0});
      const auto last = std::lower_bound(first, my_blocks_.end(), BlockKey{r + 1, 0, 0, 0});
      std::vector<BlockKey> waiting;
      for (auto it = first; it != last; ++it)
        if (previous >= 0 && touches(plan_.lattice, plan_.box, *it, previous, other_blocks_))
          waiting.push_back(*it);
      std::vector<RoundRecord> records;
      if (static_cast<std::size_t>(last - first) > waiting.size())
        run_part(r, waiting, false, records);
      if (previous >= 0) collect();
      if (!waiting.empty()) run_part(r, waiting, true, records);
      apply_to_host(host_, a_, owned_, records, doomed_);
      live_->apply(records, plan_.domain);
      std::vector<double> encoded;
      encode_records(records, encoded);
      host_.post_results(encoded, plan_.partners);
      previous = r;
    }
    if (previous >= 0) {
      collect();
      host_.finish_results();
    }
    // Per-process work of each round: the busiest process sets its time.
    for (double most : reduce_all(host_, work_, true)) done.busiest += most;
    done.processes = host_.sum(1.0);
    done.blocks = static_cast<double>(my_blocks_.size() + other_blocks_.size());
    return done;
  }

private:
  // Progress of a long stage, from this process's side (the log is the
  // first process's): it begins its `nth` round with work, `round`; the
  // blocks of the rounds before it are done here, and elsewhere but for
  // those of the round just before.
  void say_progress(int round, int nth, double seconds) const
  {
    int rounds = 0;
    for (double w : per_round_) rounds += w > 0;
    std::size_t before = 0, blocks = 0;
    for (const std::vector<BlockKey> *list : {&my_blocks_, &other_blocks_})
      for (const BlockKey &k : *list) {
        ++blocks;
        before += k[0] < round;
      }
    char line[200];
    std::snprintf(line, sizeof line,
                  "fix reinforce/invert: %s: round %d of %d begins after %.1f s; the rounds "
                  "before it hold %zu of %zu blocks\n",
                  stage_.name(), nth, rounds, seconds, before, blocks);
    host_.log(line);
  }

  // The round of a particle that is the stage's work and whose block's
  // centre this process owns (each unit of work is done by that process),
  // or -1.
  int round_of(const Particle &p) const
  {
    const int pass = stage_.pass_of(p);
    if (pass < 0 || !in_box(p.x, plan_.domain) ||
        !in_subdomain(plan_.lattice.centre_of(p.x), plan_.domain))
      return -1;
    return pass * plan_.lattice.rounds() + plan_.lattice.colour_of(p.x);
  }

  // Runs the work of round `round` in the blocks that are (waits) or are
  // not among `waiting`.
  void run_part(int round, const std::vector<BlockKey> &waiting, bool waits,
                std::vector<RoundRecord> &records)
  {
    const auto picked = [&](const Particle &p) {
      if (round_of(p) != round) return false;
      const BlockKey key = block_key(plan_.lattice, round, p.x);
      return std::binary_search(waiting.begin(), waiting.end(), key) == waits;
    };
    live_->read_by(round, round_view_);
    const StageResult result = stage_.run(round_view_, picked);
    work_[round] += static_cast<double>(result.done);
    records.insert(records.end(), result.records.begin(), result.records.end());
  }

  // The other processes' results of the oldest round posted.
  void collect()
  {
    std::vector<RoundRecord> others;
    if (!decode_records(host_.collect_results(plan_.partners), others))
      host_.fail("Fix reinforce/invert: internal error: malformed round results");
    apply_to_host(host_, a_, owned_, others, doomed_);
    live_->apply(others, plan_.domain);
  }

  HostHooks &host_;
  Stage &stage_;
  const RoundPlan &plan_;
  const AtomArrays &a_;
  std::vector<int> &doomed_;
  std::unordered_map<std::int64_t, int> owned_;    // id -> local index of the owned atom
  std::vector<double> per_round_;                  // work per round, over all processes
  std::vector<double> work_;                       // this process's work per round
  RoundsNear rounds_near_;
  std::vector<BlockKey> my_blocks_, other_blocks_;
  std::unique_ptr<LiveView> live_;
  std::vector<Particle> round_view_;
};

}    // namespace

RoundsDone run_rounds(HostHooks &host, Stage &stage, const RoundPlan &plan,
                      std::vector<Particle> view, const std::vector<int> &local,
                      const AtomArrays &a, std::vector<int> &doomed)
{
  RoundRunner runner(host, stage, plan, std::move(view), local, a, doomed);
  return runner.run();
}

}    // namespace reinforce
