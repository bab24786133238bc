#pragma once
// Factories of the two offscreen backends (used by create_offscreen_context in gl_context.cpp).
#include <memory>

#include "engine/render/gl_context.hpp"

namespace sc {

std::unique_ptr<GlContext> create_osmesa_context(int width, int height);
std::unique_ptr<GlContext> create_egl_context(int width, int height);

}  // namespace sc
