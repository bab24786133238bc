#pragma once
// Where SkillCoach finds its read-only data (assets/ and shaders/).
// Order: $SKILLCOACH_ASSET_DIR / $SKILLCOACH_SHADER_DIR, then next to the executable
// (<exe dir>/../share/skillcoach/{assets,shaders} when installed), then the source tree it was built from.
#include <filesystem>
#include <string_view>

namespace sc {

std::filesystem::path asset_dir();
std::filesystem::path shader_dir();

// asset_dir()/relative, throwing InputError naming the full path when it does not exist.
std::filesystem::path asset_path(std::string_view relative);
std::filesystem::path shader_path(std::string_view relative);

}  // namespace sc
