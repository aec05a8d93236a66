// toml++'s parser compiled here, into the scenario module, from Debian's headers
// (libtomlplusplus-dev) instead of linked from its libtomlplusplus.so.3. That library was
// built with TOML_FLOAT_CHARCONV 0 and reads every floating-point value through a fresh
// std::istringstream: 40% of the instructions of reading the 1,601-block brick wall (12,800
// coordinates). Here numbers are read by std::from_chars (GCC 12), correctly rounded as the
// stream's strtod is, so every value read is the same double. The macros that choose this are
// set for every file of ours that includes toml++ (hydrodda_toml in cmake/Dependencies.cmake).
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
