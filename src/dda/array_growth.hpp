#pragma once
// Growing the step's large arrays (the factor's blocks, the contacts, the springs) without
// touching more fresh memory than they need: fresh pages cost a page fault each on first
// touch, which on a virtual machine is some 10 µs (docs/studies/dda_step.md, "Memory:").

#include <cstddef>

namespace hydrodda::dda {

// Room for n elements in `v`, with a quarter more when it must grow: the step's arrays grow a
// little at a time as contacts come (a factor's fill, the contact list), and doubling each
// time, with the old values copied, touches fresh pages the size of the array again.
template <class Vector>
void reserve_with_headroom(Vector& v, std::size_t n) {
  if (n > v.capacity()) v.reserve(n + n / 4);
}

// `v` sized to n elements whose old values are not wanted (the caller overwrites them all):
// grown without copying them, with the headroom above.
template <class Vector>
void resize_for_overwrite(Vector& v, std::size_t n) {
  if (n > v.capacity()) v.clear();
  reserve_with_headroom(v, n);
  v.resize(n);
}

}  // namespace hydrodda::dda
