#include "app/cli/segment_image.hpp"

#include <algorithm>
#include <cfloat>
#include <span>
#include <string>

#include "app/core/fitted_text.hpp"
#include "engine/parking_view/parking_path.hpp"
#include "engine/parking_view/parking_scene.hpp"
#include "engine/render/gl_context.hpp"
#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"
#include "engine/writing/writing_scenario.hpp"
#include "engine/writing_view/canvas_geometry.hpp"
#include "engine/writing_view/canvas_painter.hpp"

namespace sc::cli {
namespace {

// ImGui lays out its first frame differently from later ones (stack notes §3), so the capture is frame 2.
constexpr int kFrames = 2;

ImU32 imgui_color(Color c) {
  auto byte = [](float v) { return static_cast<int>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
  return IM_COL32(byte(c.r), byte(c.g), byte(c.b), byte(c.a));
}

std::string legend_line(const SkillSegment& seg) {
  return "skill " + std::to_string(seg.skill) + ": steps " + std::to_string(seg.begin) + "-" +
         std::to_string(seg.end - 1);
}

// The legend's panel: top-left, as wide as its widest line. The picture is drawn to its right, so the panel
// never hides a part of the path. The caption (a file name) is cut in its middle to the legend's width or
// kCaptionShare of the image, whichever is wider, so a long name cannot squeeze the picture.
struct LegendPanel {
  ImVec2 origin;       // the caption's top-left
  float right = 0.0f;  // the panel's right edge
  std::string caption;
};
constexpr float kCaptionShare = 0.4f;

LegendPanel legend_panel(const ImGuiLayer& imgui, const std::string& caption, const Segmentation& segmentation,
                         int width) {
  const float s = imgui.scale();
  const ImVec2 origin(14.0f * s, 12.0f * s);
  float lines = 0.0f;
  for (const SkillSegment& seg : segmentation.segments)
    lines = std::max(lines, 30.0f * s + ImGui::CalcTextSize(legend_line(seg).c_str()).x);
  const auto bold = [&](const std::string& t) {
    return imgui.fonts().bold->CalcTextSizeA(ImGui::GetFontSize(), FLT_MAX, 0.0f, t.c_str()).x;
  };
  const std::string fitted =
      fitted_in_middle(caption, std::max(lines, kCaptionShare * static_cast<float>(width) - origin.x), bold);
  return {origin, origin.x + std::max(lines, bold(fitted)) + 10.0f * s, fitted};
}

// The caption and one legend line per segment on a dark panel.
void draw_legend(const ImGuiLayer& imgui, const LegendPanel& panel, const Segmentation& segmentation) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const SkillColors colors(segmentation);
  const float s = imgui.scale();
  const ImVec2 origin = panel.origin;
  const float line = ImGui::GetFontSize() * 1.35f;
  const auto rows = static_cast<float>(segmentation.segments.size() + 1);
  dl->AddRectFilled({origin.x - 8 * s, origin.y - 6 * s}, {panel.right, origin.y + line * rows + 2 * s},
                    IM_COL32(12, 15, 20, 190), 8 * s);
  dl->AddText(imgui.fonts().bold, ImGui::GetFontSize(), origin, IM_COL32(255, 255, 255, 255), panel.caption.c_str());
  for (std::size_t i = 0; i < segmentation.segments.size(); ++i) {
    const SkillSegment& seg = segmentation.segments[i];
    const float y = origin.y + line * static_cast<float>(i + 1);
    dl->AddRectFilled({origin.x, y + 3 * s}, {origin.x + 22 * s, y + line - 6 * s}, imgui_color(colors.of(seg.skill)),
                      3 * s);
    dl->AddText({origin.x + 30 * s, y}, IM_COL32(235, 238, 242, 255), legend_line(seg).c_str());
  }
}

template <typename PaintWorld>
RgbaImage render(int width, int height, Color clear, const std::string& caption, const Segmentation& segmentation,
                 const PaintWorld& paint_world) {
  auto context = create_offscreen_context_from_env(width, height);
  ImGuiLayer imgui(*context);
  Renderer2D renderer(*context);
  for (int frame = 0; frame < kFrames; ++frame) {
    imgui.make_current();
    imgui.begin_frame(1.0 / 60.0);
    const LegendPanel panel = legend_panel(imgui, caption, segmentation, width);
    const float left = std::min(panel.right + 8.0f * imgui.scale(), 0.5f * static_cast<float>(width));
    renderer.begin_frame(clear);
    paint_world(renderer, PixelViewport{left, 0.0f, static_cast<float>(width) - left, static_cast<float>(height)});
    renderer.end_frame();
    draw_legend(imgui, panel, segmentation);
    imgui.end_frame();
    context->present();
  }
  return context->read_rgba();
}

const Color kBoundaryFill = Color::hex(0xffffff);
const Color kBoundaryRing = Color::hex(0x111418);

}  // namespace

RgbaImage render_parking_segments(const ParkingTrial& trial, const Segmentation& segmentation,
                                  const std::string& caption, int width, int height) {
  const ParkingPath path = simulate_parking_path(trial);
  const std::vector<Vec2f> points = path_points(path);
  const ParkingLayout layout = make_layout(trial.scenario);
  ParkingSceneView view;
  view.layout = &layout;
  view.goal = goal_pose(trial.scenario);
  view.reverse_in = trial.scenario.reverse_in;
  view.car = car_pose_of(path.samples.back().vehicle, path.samples.back().steering);
  view.trail = points;  // only for the camera's extent; painted over by the segments
  auto sample = [&](int step) {
    return std::min(points.size() - 1, static_cast<std::size_t>(step) * parking::kSubstepsPerAction);
  };
  const SkillColors colors(segmentation);
  return render(width, height, Color::hex(0x14181f), caption, segmentation, [&](Renderer2D& r, PixelViewport viewport) {
    r.set_camera(parking_scene_camera(view, CameraMode::whole_lot, viewport));
    paint_parking_scene(r, view);
    const PathStyle round{LineJoin::round, LineCap::round};
    for (const SkillSegment& seg : segmentation.segments) {
      const std::size_t a = sample(seg.begin), b = sample(seg.end);
      if (b > a) r.polyline(std::span(points).subspan(a, b - a + 1), Stroke::world(0.45f), colors.of(seg.skill), round);
    }
    for (std::size_t i = 0; i + 1 < segmentation.segments.size(); ++i) {
      const Vec2f p = points[sample(segmentation.segments[i].end)];
      r.fill_circle(p, 0.75f, kBoundaryRing);
      r.fill_circle(p, 0.5f, kBoundaryFill);
    }
  });
}

RgbaImage render_writing_segments(const writing::WritingTrial& trial, const std::vector<writing::TracePoint>& points,
                                  const Segmentation& segmentation, const std::string& caption, int width, int height) {
  const std::vector<writing::TracePoint> gold = writing::gold_trajectory(trial.scenario).points();
  const writing_view::WritingCanvasLook look;
  const std::size_t last = points.empty() ? 0 : points.size() - 1;
  const SkillColors colors(segmentation);
  return render(width, height, look.desk, caption, segmentation, [&](Renderer2D& r, PixelViewport viewport) {
    r.set_camera(writing_view::writing_canvas_camera(viewport));
    writing_view::paint_paper(r, look);
    writing_view::paint_guide(r, gold, look);
    for (const SkillSegment& seg : segmentation.segments) {
      const std::size_t a = std::min(last, static_cast<std::size_t>(seg.begin));
      const std::size_t b = std::min(last, static_cast<std::size_t>(seg.end));
      if (b > a) writing_view::paint_ink(r, std::span(points).subspan(a, b - a + 1), colors.of(seg.skill), 4.0f);
    }
    for (std::size_t i = 0; i + 1 < segmentation.segments.size(); ++i) {
      const writing::TracePoint& p = points[std::min(last, static_cast<std::size_t>(segmentation.segments[i].end))];
      const Vec2f c{static_cast<float>(p.x), static_cast<float>(p.y)};
      r.fill_circle(c, 5.5f, kBoundaryRing);
      r.fill_circle(c, 3.8f, kBoundaryFill);
    }
  });
}

}  // namespace sc::cli
