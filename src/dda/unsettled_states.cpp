// What a step whose open–close iteration did not settle says of its contacts (System::step's
// error): those that changed state in its last pass, as a step whose forces did not settle
// names the contact farthest from touching. A contact that changed back or on (it had changed
// already in the step) is what keeps the states from settling, so those come first; each with
// its block, corner, edge, place, the states it went from and to, and its penetration in the
// pass before and in the last (> 0 overlapping its edge, < 0 a gap).

#include <algorithm>
#include <string>
#include <vector>

#include "dda/number_text.hpp"
#include "dda/system.hpp"

namespace hydrodda::dda {

namespace {

constexpr std::size_t kContactsNamed = 3;

const char* state_name(ContactState s) {
  switch (s) {
    case ContactState::open: return "open";
    case ContactState::sliding: return "sliding";
    case ContactState::locked: return "locked";
  }
  return "?";
}

}  // namespace

void System::note_state_change(ActiveContact& c, int pass, ContactState from, double penetration_from) {
  c.changed_pass = pass;
  c.changed_back = c.changed_in_step;
  c.state_before = from;
  c.penetration_before = penetration_from;
}

std::string System::describe_unsettled_states(int last_pass) const {
  if (last_pass < 0) return "it ran no open-close pass";
  std::vector<const ActiveContact*> changed;
  for (const ActiveContact& c : active_)
    if (c.changed_pass == last_pass) changed.push_back(&c);
  const std::string pass = "pass " + std::to_string(last_pass + 1);
  if (changed.empty()) return "no contact changed state in its last pass (" + pass + "), which broke bonds";
  std::stable_partition(changed.begin(), changed.end(), [](const ActiveContact* c) { return c->changed_back; });
  const auto back = std::count_if(changed.begin(), changed.end(), [](const ActiveContact* c) { return c->changed_back; });
  std::string text = std::to_string(changed.size()) + (changed.size() == 1 ? " contact" : " contacts") +
                     " changed state in its last pass (" + pass + "), " + std::to_string(back) +
                     " of them changing back or on";
  for (std::size_t i = 0; i < std::min(changed.size(), kContactsNamed); ++i) {
    const ActiveContact& c = *changed[i];
    const ContactKey& k = c.key;
    const Point at = blocks_[k.block_i].polygon[k.vertex];
    const int bond = bond_of(k);
    const char* face = bond < 0                 ? ""
                       : bond_across(k) < 0     ? " (a third sub-block's bonded face)"
                       : is_intact_bond(k)      ? " (an intact bond)"
                                                : " (a broken bond)";
    text += std::string(i == 0 ? ": " : "; ") + "vertex " + std::to_string(k.vertex) + " of block " +
            std::to_string(k.block_i) + " against edge " + std::to_string(k.edge) + " of block " +
            std::to_string(k.block_j) + face + " at (" + format_number(at.x) + ", " + format_number(at.y) + "), " +
            state_name(c.state_before) + " to " + state_name(c.record.state) + ", penetration " +
            format_number(c.penetration_before) + " then " + format_number(c.pass_penetration) + " m";
  }
  if (changed.size() > kContactsNamed) text += "; and " + std::to_string(changed.size() - kContactsNamed) + " more";
  return text;
}

}  // namespace hydrodda::dda
