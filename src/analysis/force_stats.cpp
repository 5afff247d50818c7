// Normal contact force statistics (definitions in force_stats.h).
#include "analysis/force_stats.h"

#include <algorithm>
#include <cmath>

namespace grainlab::analysis {

ForceStats force_stats(const State& s) {
  ForceStats st;
  double sum = 0;
  for (const Contact& pc : s.contacts) {
    if (!in_contact(pc)) continue;
    ++st.contacts;
    sum += pc.normal_force;
    st.max = std::max(st.max, pc.normal_force);
  }
  if (st.contacts == 0) return st;
  st.mean = sum / static_cast<double>(st.contacts);
  double var = 0;
  for (std::size_t k = 0; k < s.contacts.size(); ++k) {
    const Contact& pc = s.contacts[k];
    if (!in_contact(pc)) continue;
    var += (pc.normal_force - st.mean) * (pc.normal_force - st.mean);
    if (pc.normal_force > st.mean) st.strong.push_back(static_cast<Index>(k));
  }
  st.std_dev = std::sqrt(var / static_cast<double>(st.contacts));
  st.strong_fraction = static_cast<double>(st.strong.size()) / static_cast<double>(st.contacts);
  return st;
}

}  // namespace grainlab::analysis
