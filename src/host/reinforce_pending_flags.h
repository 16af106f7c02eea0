// The per-atom pending flag of fix reinforce/invert (one per owned and ghost
// atom) and its marks, together: the fix keeps the array, the engine's host
// (reinforce_fix_host.h) reads and sets it. Read with the host's C++
// standard (through reinforce_fix_base.h), so C++11.

#ifndef REINFORCE_PENDING_FLAGS_H
#define REINFORCE_PENDING_FLAGS_H

#include <algorithm>
#include <cstddef>
#include <vector>

namespace reinforce {

class PendingFlags {
public:
  enum Mark : int {
    kPresent = 0,    // not waiting (rebar, matrix, relocated, kept)
    kPending = 1,    // a target waiting for its new place
    kDoomed = 2      // removed: leaves at the next refresh (hosts without AtomVec::copy)
  };

  // At least n flags; new ones are kPresent.
  void grow(int n)
  {
    if (size() < n) marks.resize(n, kPresent);
  }
  void clear() { std::fill(marks.begin(), marks.end(), static_cast<int>(kPresent)); }
  int size() const { return static_cast<int>(marks.size()); }
  int &operator[](int i) { return marks[i]; }
  int operator[](int i) const { return marks[i]; }
  const int *data() const { return marks.data(); }
  std::size_t bytes() const { return marks.capacity() * sizeof(int); }

private:
  std::vector<int> marks;
};

}    // namespace reinforce

#endif
