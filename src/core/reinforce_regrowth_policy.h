// The regrowth's constants in one place, with their units (listed in
// docs/design.md, "Regrowth policy"). Lengths are shares of a radius: "r"
// of the sphere concerned, "rmin" of the smaller of a pair; counts are
// iterations (one FIRE step or one sweep over the active spheres).
#pragma once

#include <cstddef>

namespace reinforce {
namespace regrowth_policy {

// Exactness. A place the regrowth accepts overlaps nothing by more than
// kClear rmin (its settling, FIRE and sweeps stop there), whatever tol is;
// a sphere left above kRegrowthExact rmin is counted.
constexpr double kClear = 1e-13;
constexpr double kRegrowthExact = 1e-12;

// The zone. A seed moves at most kMoveShare of the width; a matrix sphere
// at distance d from the nearest seed at most that times (1 - d / width).
constexpr double kMoveShare = 0.9;

// Settling onto the bars (hard spheres): kSettlePasses passes, the first
// stepping a sphere kSettleStep r (times its mobility) towards its bar, the
// later ones less; a step or slide below kSettleSmallest r is not made.
constexpr int kSettlePasses = 30;
constexpr double kSettleStep = 0.1;
constexpr double kSettleSmallest = 1e-3;

// Compaction (soft spheres): a pull of kPull r (times the mobility) towards
// the bar for kCompactIters steps, then kRelaxIters without it (kRelaxMore
// more below kNearlyJammed rmin); up to kCompactTries, the pull times
// kPullDecay each.
constexpr double kPull = 0.1;
constexpr double kPullDecay = 0.3;
constexpr double kNearlyJammed = 1e-3;
constexpr int kCompactTries = 3;
constexpr int kCompactIters = 1000;
constexpr int kRelaxMore = 4000;

// A seed's starts: lattice points kStartSpacing r apart within its cap,
// none overlapping by more than kWorstStart r, at most kStarts of them at
// least a radius apart. It fits alone (kAloneSweeps sweeps) at any, or
// grows from the first kGrowthStarts.
constexpr double kStartSpacing = 0.25;
constexpr double kWorstStart = 0.5;
constexpr std::size_t kStarts = 4;
constexpr std::size_t kGrowthStarts = 3;
constexpr int kAloneSweeps = 30;

// Growth of a seed: from kStartScale of its radius in kGrowthSteps equal
// steps, each followed by at most kStepIters steps (fewer once no overlap
// exceeds kSettled rmin); given up when an overlap stays above kAbort rmin.
// Then at most kRelaxIters steps to kClear, else, below kNearlyClear rmin,
// kFinishIters more, then kFinalSweeps sweeps.
constexpr double kStartScale = 0.5;
constexpr int kGrowthSteps = 10;
constexpr int kStepIters = 100;
constexpr double kSettled = 1e-4;
constexpr double kAbort = 0.05;
constexpr int kRelaxIters = 2000;
constexpr double kNearlyClear = 2e-5;
constexpr int kFinishIters = 4000;
constexpr int kFinalSweeps = 200;
// Seeds grown together (grow together): once grown, the zone is judged
// every kJudgeIters steps, the most overlapped seed given up while an
// overlap exceeds kNearlyJammed rmin.
constexpr int kJudgeIters = 1000;

// grow balance: a block's zone rebuilt. Its default width kBalanceWidth
// (matrix rmax): narrower zones jam near full size (docs/design.md). Its
// seeds deleted, the deepest centre first, until the deleted volume reaches
// kBalanceShare times the volume of the seeds inside the bars (the matrix
// the bars displaced there). The rest, at their own radius, and the zone's
// matrix start at kBalanceStart of their radii and grow back in
// kBalanceStages equal stages of at most kBalanceStageIters FIRE steps
// (fewer once settled, below); while the radii are below
// kBalancePullUntil each stage starts with kBalancePullIters steps pulling
// each matrix sphere towards its bar by a force of kBalancePull r (times its
// mobility).
constexpr double kBalanceWidth = 8;
constexpr double kBalanceShare = 1.3;
constexpr double kBalanceStart = 0.8;
constexpr int kBalanceStages = 10;
constexpr int kBalanceStageIters = 300;
constexpr double kBalancePullUntil = 0.97;
constexpr int kBalancePullIters = 50;
constexpr double kBalancePull = 0.002;
// grow balance, what does not fit: a stage before the last relaxed to
// kBalanceSettled rmin (the last to kSettled). While an overlap above
// kAbort rmin is left (kNearlyJammed once grown, any at the finish), half
// of the seeds above it are given up together and the zone relaxed again,
// at most kBalanceDrops rounds; one left with no seed above it after one
// more relaxation is the matrix's: the zone jams and goes back. The finish:
// FIRE with the contact distance of each pair of moving spheres padded by
// kPad rmin, to padded overlaps of at most kPad / 2 rmin (those pairs clear
// by kPad / 2), then at the true radii to kClear.
constexpr double kBalanceSettled = 1e-3;
constexpr int kBalanceDrops = 8;
constexpr double kPad = 1e-4;

// FIRE (Bitzek et al. 2006; harmonic overlap energy, unit stiffness and
// mass): time step (start, largest, growth kFireGrow after kFireDelay
// downhill steps, halved uphill), mixing (start, decay), the largest step
// of a sphere in one iteration (kFireStep r), and the skin of its neighbour
// lists (kSkin of the largest movable radius).
constexpr double kFireDt = 0.1;
constexpr double kFireDtMax = 0.3;
constexpr double kFireGrow = 1.1;
constexpr int kFireDelay = 5;
constexpr double kFireShrink = 0.5;
constexpr double kFireAlpha = 0.1;
constexpr double kFireAlphaDecay = 0.99;
constexpr double kFireStep = 0.05;
constexpr double kSkin = 0.25;

}    // namespace regrowth_policy
}    // namespace reinforce
