// The regrowth's constants in one place, with their units (listed in
// docs/design.md, "Regrowth policy"). Lengths are shares of a radius: "r"
// of the sphere concerned, "rmin" of the smaller of a pair, "rmax" the
// largest matrix radius; counts are FIRE steps.
#pragma once

namespace reinforce {
namespace regrowth_policy {

// Exactness. The growth ends when no pair overlaps by more than kClear of
// its smaller radius beyond what it overlapped at the start; a sphere left
// above kRegrowthExact rmin is counted.
constexpr double kClear = 1e-13;
constexpr double kRegrowthExact = 1e-12;

// The zone: the matrix within kZoneWidth rmax of a seed moves, a sphere at
// distance d at most kCapShare * rmax * (1 - d / width) from where it was
// (a seed kCapShare rmax); nothing moves at the zone's edge.
constexpr double kZoneWidth = 8;
constexpr double kCapShare = 3;

// The count: the seeds deleted, deepest centre first, weigh kBalanceShare
// times their volume inside the bars.
constexpr double kBalanceShare = 1.3;

// The growth: the zone's radii start at kGrowStart and grow back to full
// size in kStages equal stages of at most kStageSteps FIRE steps, each
// ended early once no overlap exceeds kStageSettled rmin; while the radii
// are below kPullUntil each stage starts with kPullSteps steps pulling a
// matrix sphere towards its nearest bar sphere (within kPullRange rmax) by
// a force of kPull r times its mobility.
constexpr double kGrowStart = 0.8;
constexpr int kStages = 10;
constexpr int kStageSteps = 300;
constexpr double kStageSettled = 1e-3;
constexpr double kPullUntil = 0.97;
constexpr int kPullSteps = 50;
constexpr double kPull = 0.003;
constexpr double kPullRange = 8;

// What does not fit: while a stage leaves an overlap above kAbort rmin,
// half of the growing seeds above it are given up together (the deepest
// first) and the zone relaxed again, at most kDrops rounds; an overlap
// left above it with no seed above it is the matrix's own: the zone jams.
// Grown, the same with kNearlyJammed after at most kJudgeSteps steps.
constexpr double kAbort = 0.05;
constexpr double kNearlyJammed = 1e-3;
constexpr int kJudgeSteps = 1000;
constexpr int kDrops = 8;

// The finish: the contact distance of every pair padded by kPad of its
// smaller radius, relaxed until no padded overlap exceeds kPad / 2 (at
// most kFinishSteps steps); then the exact check at the true radii.
constexpr double kPad = 1e-4;
constexpr int kFinishSteps = 2000;

// FIRE (Bitzek et al. 2006; harmonic overlap energy, unit stiffness and
// mass): time step (start, largest, growth kFireGrow after kFireDelay
// downhill steps, halved uphill), mixing (start, decay), the largest step
// of a sphere in one iteration (kFireStep r), and the skin of the
// neighbour lists (kSkin rmax).
constexpr double kFireDt = 0.1;
constexpr double kFireDtMax = 0.3;
constexpr double kFireGrow = 1.1;
constexpr int kFireDelay = 5;
constexpr double kFireShrink = 0.5;
constexpr double kFireAlpha = 0.1;
constexpr double kFireAlphaDecay = 0.99;
constexpr double kFireStep = 0.05;
constexpr double kSkin = 0.3;

}    // namespace regrowth_policy
}    // namespace reinforce
