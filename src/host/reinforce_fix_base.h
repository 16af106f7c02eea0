// fix reinforce/invert on a LAMMPS-family host (LAMMPS, LIGGGHTS): the fix
// written once. It parses the arguments, checks the set-up, runs the
// engine (reinforce::run_invocation, src/core) at the right points of a run
// on the host's atoms and communication (reinforce_fix_host.h), keeps the
// per-atom pending flag, and reports f_ID[n]. Each host derives its
// FixReinforceInvert from it and supplies only what differs: its
// communication and rigid-body checks, the walls it can read, its ghost
// reach, the per-atom communication hooks named as that host names them,
// and (current LAMMPS) the host's neighbour list. docs/design.md, "Hosts".
//
// This header is read by the host's own files (style_fix.h) with the host's
// C++ standard, so it names no engine type beyond a declaration; the
// engine, which needs C++17, is reached from the .cpp files only.

#ifndef REINFORCE_FIX_BASE_H
#define REINFORCE_FIX_BASE_H

#include "fix.h"

#include "reinforce_pending_flags.h"

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

namespace reinforce {
struct FixOptions;
class Boundaries;
}    // namespace reinforce

namespace LAMMPS_NS {

class Region;
struct FixHostView;

class ReinforceFixBase : public Fix {
public:
  ReinforceFixBase(class LAMMPS *, int, char **);
  ~ReinforceFixBase() override;
  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  void post_run() override;
  double compute_vector(int) override;

  // The per-atom pending flag (1 = a target waiting for its new place): it
  // follows atoms that migrate between rounds and reaches their ghosts.
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  double memory_usage() override;

protected:
  // The checks every host makes at the fix command and at each init():
  // atom style, box, groups, region, then check_host().
  void check_setup();
  bool done() const;    // N = 0, relocated once: nothing more to do or check
  // The forward communication (the pending flags, or the engine's rows),
  // for the host's own hook names: pack_forward returns the values per atom.
  int pack_forward(int n, const int *list, double *buf, int pbc_flag, const int *pbc) const;
  void unpack_forward(int n, int first, const double *buf);
  // One ERROR line (on every process; does not return), one WARNING line
  // (rank 0), one log line (rank 0, screen and log file).
  void fail(const char *file, int line, const std::string &message);
  void warn(const std::string &message);
  void log(const std::string &line);

  // ---- What each host supplies.
  // Refusals of set-ups that would hide neighbours or that the fix cannot
  // handle on this host (its communication styles, dynamic groups).
  virtual void check_host() = 0;
  // Does local atom i belong to a rigid body of fix `other`?
  virtual bool in_body(Fix &other, int i) = 0;
  // Reads the walls of a wall fix that acts on the matrix, for the engine
  // (walls_in_view); returns what it read, for the log, or "" when it
  // cannot see that fix's geometry. forget_walls() starts an invocation.
  virtual std::string read_walls(Fix &wall);
  virtual void forget_walls() {}
  virtual std::shared_ptr<const reinforce::Boundaries> walls_in_view();
  // Refuses a region the fix cannot keep whole spheres inside.
  virtual void check_region(Region &) {}
  // How far ghost atoms reach beyond the subdomain in dimension d, and the
  // ghost cutoff (comm_modify cutoff) that makes them reach `reach`.
  virtual double ghost_reach(int d);
  virtual double ghost_cutoff_for(double reach) { return reach; }
  virtual void ghost_cutoff_restored() {}
  // The host's own neighbour list for the engine (HostHooks): none by default.
  virtual bool build_neighbour_lists(double cutoff);
  virtual void neighbours(int local, std::vector<int> &out);

  std::unique_ptr<reinforce::FixOptions> parsed;    // the fix's arguments
  reinforce::FixOptions &options;
  int rebar_group = -1, rebar_bit = 0;

private:
  class Region *region = nullptr;
  reinforce::PendingFlags pending;
  bool invoked = false;               // the relocation at the start of the first run is done
  bool setup_seen = false;            // setup_pre_exchange ran in this run's setup
  bool lost_matrix_warned = false;    // this run's WARNING on matrix lost by the regrowth
  std::vector<double> totals;         // f_ID[1..], the latest invocation
  // The atoms this invocation moved in the group of each fix spring/self:
  // their anchors are still the old positions.
  struct Anchors {
    std::string id;
    int bit;
    std::unordered_set<std::int64_t> moved;
  };
  std::vector<Anchors> anchors;

  // The rows the forward communication sends instead of the flags (null:
  // the flags), their width and whether the first three are a position.
  double *rows = nullptr;
  int row_width = 1;
  bool rows_are_positions = false;

  void invoke();
  FixHostView host_view();
  void forward_values(std::vector<double> &values, int width, bool positions);
  bool shares_matrix_atoms(const Fix &other);
  void check_bodies();
  void check_walls();
  void find_other_rebar(int &bits, std::string &names);
  void find_anchors();
  void warn_anchors();
};

}    // namespace LAMMPS_NS

#endif
