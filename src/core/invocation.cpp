#include "invocation.h"

#include "cell_grid.h"
#include "round_records.h"
#include "schedule.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace reinforce {

namespace {

// The engine's view of the atoms that can matter: those within `margin` of
// a rebar sphere and inside the domain's view bounds. Every atom is an
// obstacle; pending ones are vacant; only matrix atoms of the fix group are
// pushed.
std::vector<Particle> make_view(const AtomArrays &a, double margin, const Domain &domain,
                                std::vector<int> &local)
{
  std::vector<unsigned char> rebar(a.nall);
  for (int i = 0; i < a.nall; ++i) rebar[i] = (a.mask[i] & a.rebar_bit) != 0;
  local = spheres_near_rebar(a.nall, a.x, a.radius, rebar.data(), margin);
  local.erase(
      std::remove_if(local.begin(), local.end(),
                     [&](int i) {
                       for (int d = 0; d < 3; ++d)
                         if (!(a.x[i][d] >= domain.view_lo[d] && a.x[i][d] <= domain.view_hi[d]))
                           return true;
                       return false;
                     }),
      local.end());
  std::vector<Particle> view;
  view.reserve(local.size());
  for (int i : local) {
    Particle p;
    p.x = {a.x[i][0], a.x[i][1], a.x[i][2]};
    p.r = a.radius[i];
    p.id = a.tag[i];
    p.role = rebar[i] ? Role::Rebar : (a.pending[i] ? Role::Target : Role::Matrix);
    p.owned = i < a.nlocal;
    p.other_rebar = !rebar[i] && (a.mask[i] & a.frozen_bits) != 0;
    p.pushable = (a.mask[i] & a.group_bit) != 0 && !p.other_rebar;
    view.push_back(p);
  }
  return view;
}

bool is_matrix(const AtomArrays &a, int i)
{
  return (a.mask[i] & a.group_bit) && !(a.mask[i] & (a.rebar_bit | a.frozen_bits));
}

// In the fix group, but in the rebar of another reinforce/invert fix.
bool is_left_alone(const AtomArrays &a, int i)
{
  return (a.mask[i] & a.group_bit) && !(a.mask[i] & a.rebar_bit) && (a.mask[i] & a.frozen_bits);
}

// The one copy of an atom that lies in the box (periodic images lie outside).
bool in_box(Vec3 x, const Domain &d)
{
  for (int k = 0; k < 3; ++k)
    if (d.periodic[k] && (x[k] < d.lo[k] || x[k] >= d.hi[k])) return false;
  return true;
}

bool in_subdomain(Vec3 x, const Domain &d)
{
  for (int k = 0; k < 3; ++k)
    if (x[k] < d.sub_lo[k] || x[k] >= d.sub_hi[k]) return false;
  return true;
}

std::string format(const char *fmt, double a, double b = 0)
{
  char line[300];
  std::snprintf(line, sizeof line, fmt, a, b);
  return line;
}

// Every round's results go to the partner processes (exchange_partners: all
// that can see or own an atom they change) as records by atom ID
// (round_records.h). The owner of an atom applies them to the host's atom;
// each partner applies them to its view, so that the next round needs no
// migration and no new ghosts from the host. The records of one round touch
// each atom once at most (the blocks of a round are independent), so a
// process may apply its own records and the others' in either order.
// The share of targets deleted for want of a void above which the log says
// why (docs/fix_reinforce_invert.rst, "Output").
constexpr double kManyUnplaced = 0.1;
// size keep: targets split into this many classes of radius (equal widths
// of the targets' range), largest first. More classes give the largest
// targets the voids first across more of the scene, but fewer targets per
// round, and so a less even share between processes: 3 kept the quality
// scenes' shell ratios of 4 within their standard error and let the small
// beam run 1.73 times faster on 2 processes (4: 1.68; docs/design.md).
constexpr int kSizeClasses = 3;
// Element-wise sum (or max) over the processes of vectors of one length, by
// one gather: one collective instead of one per element.
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
    case RecordKind::Placed: host.move(i, rec.v, rec.r); break;
    case RecordKind::Deleted: doomed.push_back(i); break;
    case RecordKind::Kept: host.set_pending(i, false); break;
    case RecordKind::Pushed:
      host.move(i, Vec3{a.x[i][0], a.x[i][1], a.x[i][2]} + rec.v, a.radius[i]);
      break;
    }
  }
}

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
      if (what == RecordKind::Kept) {
        for (std::size_t c : copies) view_[c].role = Role::Matrix;
        continue;
      }
      if (copies.empty() && what != RecordKind::Placed) continue;    // neither seen nor to be seen here
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

// The line that says why many targets were deleted, naming what is true of
// them: no spheres around them within `search`, a bar larger than the box,
// or no void in the accepted radius range (the usual cause in a dense
// packing of close radii, where few voids take even the smallest).
std::string unplaced_line(const Stats &s, std::int64_t no_place, double rmin, double rmax,
                          double search, double rebar_rmax, bool bar_exceeds_box)
{
  char part[300];
  std::snprintf(part, sizeof part,
                "fix reinforce/invert: unplaced: %lld of %lld targets (%.0f%%) were deleted: ",
                static_cast<long long>(no_place), static_cast<long long>(s.targets),
                100.0 * no_place / s.targets);
  std::string line = part;
  std::vector<std::string> why;
  if (bar_exceeds_box) {
    std::snprintf(part, sizeof part, "a bar sphere (radius %g) is larger than the box",
                  rebar_rmax);
    why.emplace_back(part);
  }
  if (s.isolated > 0) {
    std::snprintf(part, sizeof part,
                  "%lld had fewer than four neighbours within search %g (the search keyword "
                  "widens it)",
                  static_cast<long long>(s.isolated), search);
    why.emplace_back(part);
  }
  const std::int64_t no_void = no_place - s.isolated;
  if (no_void > 0) {
    // Close radii: the largest at most 1.5 times the smallest accepted.
    const bool close = rmax <= 1.5 * rmin;
    std::snprintf(part, sizeof part,
                  "%lld found no void with a radius in [%g, %g] (%sthe radius keyword widens "
                  "the accepted range)",
                  static_cast<long long>(no_void), rmin, rmax,
                  close ? "in a dense packing of close radii few voids take even the smallest; "
                        : "");
    why.emplace_back(part);
  }
  for (std::size_t k = 0; k < why.size(); ++k) line += (k ? "; " : "") + why[k];
  return line + "; unplaced keep leaves them in place\n";
}

}    // namespace

std::array<double, kOutputSize> output_vector(const Totals &t)
{
  const Stats &s = t.stats;
  return {static_cast<double>(s.targets),
          static_cast<double>(s.relocated),
          t.deleted,
          t.kept,
          s.volume_before,
          s.volume_after,
          s.max_overlap,
          static_cast<double>(s.solves),
          t.seconds,
          t.packing_overlaps,
          s.max_kept_overlap,
          s.volume_removed,
          static_cast<double>(s.pushed),
          s.max_push,
          static_cast<double>(s.sweeps),
          static_cast<double>(s.displaced),
          static_cast<double>(t.rounds)};
}

Totals run_invocation(HostHooks &host, const FixOptions &options)
{
  const double start = host.wall_time();
  host.refresh();

  // Radius range of the matrix and the largest sphere, over all processes.
  AtomArrays a = host.atoms();
  double matrix_rmin = INFINITY, matrix_rmax = 0, largest = 0, rebar_count = 0, matrix_count = 0;
  double bad_matrix = 0, bad_rebar = 0;    // an id with radius 0 (or not finite)
  for (int i = 0; i < a.nlocal; ++i) {
    const double r = a.radius[i];
    const bool good = r > 0 && std::isfinite(r);
    if (good) largest = std::max(largest, r);
    if (a.mask[i] & a.rebar_bit) {
      rebar_count += 1;
      if (!good && bad_rebar == 0) bad_rebar = static_cast<double>(a.tag[i]);
    } else if (is_matrix(a, i)) {
      matrix_count += 1;
      if (!good && bad_matrix == 0) bad_matrix = static_cast<double>(a.tag[i]);
      matrix_rmin = std::min(matrix_rmin, r);
      matrix_rmax = std::max(matrix_rmax, r);
    }
  }
  if (host.sum(rebar_count) == 0)
    host.fail("Fix reinforce/invert rebar group '" + options.rebar_group + "' is empty");
  bad_rebar = host.max(bad_rebar);
  if (bad_rebar > 0)
    host.fail(format("Fix reinforce/invert: rebar atom %.0f has radius 0; rebar spheres need "
                     "a radius > 0",
                     bad_rebar));
  bad_matrix = host.max(bad_matrix);
  if (bad_matrix > 0)
    host.fail(format("Fix reinforce/invert: matrix atom %.0f has radius 0; matrix spheres need "
                     "a radius > 0",
                     bad_matrix));
  matrix_rmin = -host.max(-matrix_rmin);
  matrix_rmax = host.max(matrix_rmax);
  largest = host.max(largest);

  Totals totals;
  const bool any_matrix = host.sum(matrix_count) > 0;
  double unit = any_matrix ? matrix_rmin : 0;    // of the overlaps reported: the settings' rmin
  double accepted_rmax = matrix_rmax;    // the settings' rmax: the top of the accepted radii
  double search = 0, rebar_rmax = 0;     // for the unplaced line
  bool bar_exceeds_box = false;
  if (!any_matrix)
    host.warn("Fix reinforce/invert has no matrix sphere (an atom of the fix group outside the "
              "rebar group): nothing to relocate");
  if (any_matrix) {
    const Domain box = host.placement_domain();
    const double diagonal = norm(box.hi - box.lo);
    Settings settings;
    try {
      settings = make_settings(options, matrix_rmin, matrix_rmax, diagonal);
    } catch (const OptionError &e) {
      host.fail(e.what());
    }
    unit = settings.rmin;
    accepted_rmax = settings.rmax;
    if (settings.size == SizeMode::Fit && settings.rmin == settings.rmax)
      host.log(format("fix reinforce/invert: the radius range is the single radius %g: with "
                      "size fit only voids of exactly that radius fit; size keep (the default) "
                      "or the radius keyword widen it\n",
                      settings.rmin));
    const Footprint reach = footprint(settings, matrix_rmax, largest);
    const BlockLattice lattice =
        make_block_lattice(box.lo, box.hi, box.periodic, reach.write + reach.read);
    // The owner of a block's centre sees the whole block plus the read
    // reach: how far a block reaches past a subdomain depends on where the
    // subdomain's faces fall on the lattice, so the largest over processes.
    const double beyond = host.max(lattice.reach_beyond(box.sub_lo, box.sub_hi));
    const double cutoff = beyond + reach.read;
    if (!std::isfinite(cutoff))
      host.fail("Fix reinforce/invert: the reach of the relocation is not finite");
    host.ensure_ghost_cutoff(cutoff);
    // Everything a relocation reads lies within reach.read of a target's
    // centre, and a target touches a bar: the view needs no more. Nor does
    // it need more than the cutoff past the subdomain, whatever the host's
    // ghosts hold: the results of the rounds reach this process only from
    // the processes that can change something within that (exchange_partners).
    const double margin = reach.read + 2 * largest;
    Domain domain = host.placement_domain();
    for (int d = 0; d < 3; ++d) {
      domain.view_lo[d] = std::max(domain.view_lo[d], domain.sub_lo[d] - cutoff);
      domain.view_hi[d] = std::min(domain.view_hi[d], domain.sub_hi[d] + cutoff);
    }
    const std::vector<int> partners = exchange_partners(host, domain, beyond, reach.write, cutoff);

    a = host.atoms();
    std::vector<int> local;
    std::vector<Particle> view = make_view(a, margin, domain, local);
    // Targets, and how many fall in each round of the schedule. With size
    // keep the targets are split into size classes, largest first, each
    // class a pass over the colours: the voids that hold a sphere as it is
    // go to the largest targets of the whole scene first, not only of
    // their block (docs/design.md, "Rounds").
    //
    // The overlap check: owned matrix spheres of the fix group that overlap
    // a rebar sphere by more than tol * min radius. Each process marks only
    // its own (owned) targets, so a list with rows for owned atoms is enough.
    // The host's list answers when it has one that reaches matrix-rebar
    // contact (source-built LAMMPS: its occasional full list); else, or when
    // it is shorter (radii grew since the host set it up), the engine's grid
    // over the view does (find_targets). Both decide each pair with
    // spheres_overlap on the same coordinates, and both see every rebar
    // sphere a target can overlap: a target touches a bar, so it is in the
    // view, and the rebar spheres it overlaps lie within matrix rmax +
    // rebar rmax of it (owned or ghost). So both give the same targets, in
    // view order (tests: Invocation.HostListFindsTheSameTargets*, and
    // src_lammps_same_as_packaged_host_list against lmp_reinforce).
    for (const Particle &p : view)
      if (p.role == Role::Rebar) rebar_rmax = std::max(rebar_rmax, p.r);
    const double contact = matrix_rmax + host.max(rebar_rmax);
    std::vector<std::size_t> overlapping;
    if (host.build_neighbour_lists(contact)) {
      std::vector<int> near;
      for (std::size_t k = 0; k < view.size(); ++k) {
        if (!view[k].owned || !is_matrix(a, local[k])) continue;
        host.neighbours(local[k], near);
        for (int j : near) {
          if (!(a.mask[j] & a.rebar_bit)) continue;
          if (spheres_overlap(view[k].x, view[k].r, Vec3{a.x[j][0], a.x[j][1], a.x[j][2]},
                              a.radius[j], settings.tol)) {
            overlapping.push_back(k);
            break;
          }
        }
      }
    } else {
      overlapping = find_targets(view, settings.tol);
    }
    std::vector<std::size_t> found;
    double target_rmin = INFINITY, target_rmax = 0, left_alone = 0;
    for (std::size_t k : overlapping) {
      if (is_left_alone(a, local[k])) left_alone += 1;
      if (!is_matrix(a, local[k])) continue;
      host.set_pending(local[k], true);
      found.push_back(k);
      target_rmin = std::min(target_rmin, view[k].r);
      target_rmax = std::max(target_rmax, view[k].r);
    }
    target_rmin = -host.max(-target_rmin);
    target_rmax = host.max(target_rmax);
    left_alone = host.sum(left_alone);
    if (left_alone > 0)
      host.log(format("fix reinforce/invert: left alone %.0f atoms that overlap the bars: they "
                      "are rebar of ",
                      left_alone) +
               a.frozen_by + "\n");
    rebar_rmax = host.max(rebar_rmax);
    for (int d = 0; d < 3; ++d)
      bar_exceeds_box = bar_exceeds_box || 2 * rebar_rmax > domain.hi[d] - domain.lo[d];
    search = settings.search;
    const int classes = settings.size == SizeMode::Keep ? kSizeClasses : 1;
    const double class_width = (target_rmax - target_rmin) / classes;
    auto size_class = [&](double r) {
      if (!(class_width > 0)) return 0;
      const double c = std::floor((target_rmax - r) / class_width);
      return c < 0 ? 0 : (c >= classes ? classes - 1 : static_cast<int>(c));
    };
    std::vector<double> per_round(static_cast<std::size_t>(classes) * lattice.rounds(), 0.0);
    for (std::size_t k : found)
      per_round[size_class(view[k].r) * lattice.rounds() + lattice.colour_of(view[k].x)] += 1;
    per_round = reduce_all(host, per_round, false);
    double any = 0;
    for (double n : per_round) any += n;
    if (any > 0) {
      // The ghosts learn which atoms are targets (a forward communication:
      // the atoms and their order stay as they are).
      host.forward_pending();
      a = host.atoms();
      for (std::size_t k = 0; k < view.size(); ++k)
        if (view[k].role != Role::Rebar)
          view[k].role = a.pending[local[k]] ? Role::Target : Role::Matrix;
      double largest_packing = 0;
      totals.packing_overlaps = host.sum(static_cast<double>(
          count_packing_overlaps(view, settings.tol, settings.rmin, largest_packing)));
      totals.packing_max_overlap = host.max(largest_packing);
      if (totals.packing_overlaps > 0)
        host.log(format("fix reinforce/invert: the packing near the bars already has %.0f "
                        "overlapping pairs (largest %.2e rmin); they are left as they are\n",
                        totals.packing_overlaps, totals.packing_max_overlap));
    }

    std::unordered_map<std::int64_t, int> owned;    // id -> local index of the owned atom
    for (std::size_t k = 0; k < view.size(); ++k)
      if (view[k].owned) owned[view[k].id] = local[k];
    std::vector<int> doomed;
    std::vector<double> work(per_round.size(), 0.0);    // this process's targets per round
    // Each target is relocated by the process that owns its block's centre.
    auto round_of = [&](const Particle &p) {
      if (p.role != Role::Target || !in_box(p.x, domain) ||
          !in_subdomain(lattice.centre_of(p.x), domain))
        return -1;
      return size_class(p.r) * lattice.rounds() + lattice.colour_of(p.x);
    };
    double view_largest = settings.rmax;
    for (const Particle &p : view) view_largest = std::max(view_largest, p.r);
    // Rounds are a bit each in RoundsNear: at most 3 classes x 8 colours.
    static_assert(kSizeClasses * 8 <= 64, "a round per bit of RoundsNear");
    RoundsNear rounds_near(footprint(settings, target_rmax, view_largest).read);
    for (const Particle &p : view) {
      const int round = round_of(p);
      if (round >= 0) rounds_near.add_target(p.x, round);
    }
    // The blocks that hold this process's targets, per round, and the other
    // processes' ones. In a round, this process first relocates its blocks
    // that do not touch (share a face, edge or corner with) another
    // process's block of the round before, then collects that round's
    // results from the others, then relocates the rest: a block reads
    // nothing another process changed in a block not touching it (blocks
    // are at least write + read reach wide), so the work waits only where
    // it must, and the results are those of relocating the rounds one after
    // the other (docs/design.md, "Overlapping the exchange").
    std::vector<BlockKey> my_blocks;
    for (const Particle &p : view) {
      const int round = round_of(p);
      if (round >= 0) my_blocks.push_back(block_key(lattice, round, p.x));
    }
    std::sort(my_blocks.begin(), my_blocks.end());
    my_blocks.erase(std::unique(my_blocks.begin(), my_blocks.end()), my_blocks.end());
    const std::vector<BlockKey> other_blocks = others_blocks(host, my_blocks);
    LiveView live(std::move(view), rounds_near);
    std::vector<Particle> round_view;
    auto relocate_part = [&](int round, const std::vector<BlockKey> &waiting, bool waits,
                             std::vector<RoundRecord> &records) {
      auto picked = [&](const Particle &p) {
        if (round_of(p) != round) return false;
        const BlockKey key = block_key(lattice, round, p.x);
        return std::binary_search(waiting.begin(), waiting.end(), key) == waits;
      };
      live.read_by(round, round_view);
      const Relocation rel = relocate_targets(round_view, settings, domain, options.keep_unplaced,
                                              totals.stats, picked);
      work[round] += static_cast<double>(rel.targets.size());
      const std::vector<RoundRecord> mine = records_of(rel, options.keep_unplaced);
      records.insert(records.end(), mine.begin(), mine.end());
    };
    auto collect = [&]() {
      std::vector<RoundRecord> others;
      if (!decode_records(host.collect_results(partners), others))
        host.fail("Fix reinforce/invert: internal error: malformed round results");
      apply_to_host(host, a, owned, others, doomed);
      live.apply(others, domain);
    };
    int previous = -1;    // the round whose others' results are still to collect
    for (std::size_t round = 0; round < per_round.size(); ++round) {
      if (per_round[round] == 0) continue;
      totals.rounds++;
      const int r = static_cast<int>(round);
      const auto first = std::lower_bound(my_blocks.begin(), my_blocks.end(), BlockKey{r, 0, 0, 0});
      const auto last = std::lower_bound(first, my_blocks.end(), BlockKey{r + 1, 0, 0, 0});
      std::vector<BlockKey> waiting;
      for (auto it = first; it != last; ++it)
        if (previous >= 0 && touches(lattice, box, *it, previous, other_blocks))
          waiting.push_back(*it);
      std::vector<RoundRecord> records;
      if (static_cast<std::size_t>(last - first) > waiting.size())
        relocate_part(r, waiting, false, records);
      if (previous >= 0) collect();
      if (!waiting.empty()) relocate_part(r, waiting, true, records);
      apply_to_host(host, a, owned, records, doomed);
      live.apply(records, domain);
      std::vector<double> encoded;
      encode_records(records, encoded);
      host.post_results(encoded, partners);
      previous = r;
    }
    if (previous >= 0) {
      collect();
      host.finish_results();
    }
    host.remove(doomed);
    const double targets = host.sum(static_cast<double>(totals.stats.targets));
    // Per-process work of each round: the busiest process sets its time.
    double busiest = 0;
    for (double most : reduce_all(host, work, true)) busiest += most;
    const double processes = host.sum(1.0);
    // Blocks with targets, summed over the rounds: per round, the most
    // processes that can have work.
    const double blocks = static_cast<double>(my_blocks.size() + other_blocks.size());
    if (totals.rounds > 0) {
      // Balance: the targets over what the busiest process of each round
      // would do if every process were as busy (1 = even).
      char line[300];
      std::snprintf(
          line, sizeof line,
          "fix reinforce/invert: schedule: %d rounds, %.0f targets in %.0f blocks, busiest "
          "process %.0f targets over the rounds, balance %.2f over %.0f processes\n",
          totals.rounds, targets, blocks, busiest, targets / (busiest * processes), processes);
      host.log(line);
    }
    host.restore_ghost_cutoff();
  }

  Stats &s = totals.stats;
  auto count = [](std::int64_t n) { return static_cast<double>(n); };
  const std::vector<double> sums = reduce_all(
      host,
      {count(s.targets), count(s.relocated), count(s.unplaced), count(s.displaced), count(s.solves),
       count(s.pushed), count(s.sweeps), s.volume_before, s.volume_after, s.volume_removed,
       count(s.isolated)},
      false);
  s.targets = static_cast<std::int64_t>(sums[0]);
  s.relocated = static_cast<std::int64_t>(sums[1]);
  s.unplaced = static_cast<std::int64_t>(sums[2]);
  s.displaced = static_cast<std::int64_t>(sums[3]);
  s.solves = static_cast<std::int64_t>(sums[4]);
  s.pushed = static_cast<std::int64_t>(sums[5]);
  s.sweeps = static_cast<std::int64_t>(sums[6]);
  s.volume_before = sums[7];
  s.volume_after = sums[8];
  s.volume_removed = sums[9];
  s.isolated = static_cast<std::int64_t>(sums[10]);
  const std::vector<double> maxima =
      reduce_all(host, {s.max_overlap, s.max_kept_overlap, s.max_push}, true);
  s.max_overlap = maxima[0];
  s.max_kept_overlap = maxima[1];
  s.max_push = maxima[2];
  totals.deleted = options.keep_unplaced ? 0 : static_cast<double>(s.unplaced);
  totals.kept = options.keep_unplaced ? static_cast<double>(s.unplaced) : 0;
  totals.seconds = host.max(host.wall_time() - start);
  host.log(summary_line(s, options.keep_unplaced, totals.seconds, totals.rounds, unit));
  // Many targets that found no place: say why and what changes it.
  const std::int64_t no_place = s.unplaced - s.displaced;
  if (!options.keep_unplaced && s.targets > 0 && no_place >= kManyUnplaced * s.targets)
    host.log(unplaced_line(s, no_place, unit, accepted_rmax, search, rebar_rmax, bar_exceeds_box));
  return totals;
}

}    // namespace reinforce
