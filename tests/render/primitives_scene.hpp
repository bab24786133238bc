#pragma once
// A fixed scene that exercises every Renderer2D primitive (and a world-anchored ImGui label), used by the
// golden tests. `variant` 1 moves one rectangle slightly: the deliberately changed scene the harness must catch.
#include <memory>

#include "engine/render/gl_context.hpp"
#include "engine/render/rgba_image.hpp"

namespace sc::test {

constexpr int kPrimitivesWidth = 640;
constexpr int kPrimitivesHeight = 400;

// Renders on `context` (already sized) with a fresh Renderer2D and ImGuiLayer: frames >= 2.
RgbaImage render_primitives_scene(GlContext& context, int variant = 0, int frames = 2);

}  // namespace sc::test
