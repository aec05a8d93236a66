#pragma once

namespace hydrodda::cli {
inline constexpr const char* kVersion = "0.1.0";
}
