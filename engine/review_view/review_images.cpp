#include "engine/review_view/review_images.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "engine/render/imgui_layer.hpp"
#include "engine/render/renderer2d.hpp"
#include "engine/review_view/review_palette.hpp"

namespace sc::review_view {
namespace {

constexpr ImU32 kCaptionText = IM_COL32(236, 239, 244, 255);
constexpr ImU32 kCaptionMuted = IM_COL32(160, 170, 185, 255);
const Color kBackground = Color::hex(0x14181f);

// One frame: the world through `paint` into the left `world_width` pixels, then ImGui text through `text`.
template <typename Paint, typename Text>
RgbaImage render(GlContext& context, int width, int height, Paint&& paint, Text&& text) {
  context.make_current();
  context.resize(width, height);
  Renderer2D renderer(context);
  ImGuiLayer imgui(context);
  // ImGui's first frame differs from later ones (fonts settle), so the image is the second frame.
  for (int frame = 0; frame < 2; ++frame) {
    renderer.begin_frame(kBackground);
    paint(renderer);
    renderer.end_frame();
    imgui.begin_frame(1.0 / 60.0);
    text(imgui);
    imgui.end_frame();
  }
  context.present();
  return context.read_rgba();
}

float text_lines(ImDrawList& dl, ImVec2 at, const std::vector<std::string>& lines, float wrap) {
  for (const auto& line : lines) {
    dl.AddText(nullptr, 0.0f, at, kCaptionMuted, line.c_str(), nullptr, wrap);
    at.y += ImGui::CalcTextSize(line.c_str(), nullptr, false, wrap).y + 4.0f;
  }
  return at.y;
}

}  // namespace

RgbaImage render_trial_image(GlContext& context, const TrialPicture& picture, const TrialImageText& text, int width,
                             int height) {
  const float panel = std::min(420.0f, width * 0.36f);
  const PixelViewport world{0, 0, static_cast<float>(width) - panel, static_cast<float>(height)};
  return render(
      context, width, height,
      [&](Renderer2D& r) {
        r.set_camera(trial_picture_camera(picture, world));
        paint_trial_picture(r, picture);
      },
      [&](ImGuiLayer& imgui) {
        ImDrawList& dl = *ImGui::GetBackgroundDrawList();
        const float s = imgui.scale(), fs = ImGui::GetFontSize();
        const float x = world.width + 16.0f * s, wrap = panel - 28.0f * s;
        float y = 14.0f * s;
        dl.AddText(imgui.fonts().bold, fs, {x, y}, kCaptionText, text.title.c_str(), nullptr, wrap);
        y += imgui.fonts().bold->CalcTextSizeA(fs, 1e9f, wrap, text.title.c_str()).y + 8.0f * s;
        y = text_lines(dl, {x, y}, text.lines, wrap) + 8.0f * s;
        // What the lines mean, then one swatch per skill.
        const bool parking = picture.task == TaskKind::parking;
        dl.AddLine({x, y + fs * 0.5f}, {x + fs * 1.6f, y + fs * 0.5f}, IM_COL32(255, 226, 138, 255), 5.0f * s);
        dl.AddText({x + fs * 2.2f, y}, kCaptionText, "this trial, coloured by skill; dots: boundaries");
        y += fs * 1.35f;
        if (picture.expert) {
          dl.AddLine({x, y + fs * 0.5f}, {x + fs * 1.6f, y + fs * 0.5f}, to_u32(kExpertRibbon.with_alpha(0.8f)),
                     fs * 0.8f);
          dl.AddText({x + fs * 2.2f, y}, kCaptionText, parking ? "expert's path (same scenario)" : "expert's pen path");
          y += fs * 1.35f;
        }
        if (picture.ghost) {
          for (int i = 0; i < 3; ++i)
            dl.AddLine({x + i * fs * 0.6f, y + fs * 0.5f}, {x + i * fs * 0.6f + fs * 0.35f, y + fs * 0.5f},
                       parking ? IM_COL32(255, 255, 255, 230) : IM_COL32(120, 140, 180, 255), 3.0f * s);
          dl.AddText({x + fs * 2.2f, y}, kCaptionText, "drill's ghost path");
          y += fs * 1.35f;
        }
        y += 6.0f * s;
        for (const LegendEntry& e : text.legend) {
          dl.AddRectFilled({x, y + fs * 0.15f}, {x + fs * 0.8f, y + fs * 0.95f}, picture.palette.color_u32(e.skill),
                           3.0f);
          const std::string label = std::to_string(e.skill) + "  " + e.label;
          dl.AddText(nullptr, 0.0f, {x + fs * 1.2f, y}, kCaptionText, label.c_str(), nullptr, wrap - fs * 1.2f);
          y += ImGui::CalcTextSize(label.c_str(), nullptr, false, wrap - fs * 1.2f).y + 4.0f * s;
        }
        const float plot_h = std::min(180.0f * s, static_cast<float>(height) - y - 24.0f * s);
        if (!text.plot.rewards.empty() && plot_h > 80.0f * s)
          draw_reward_plot(dl, {x - 6.0f * s, static_cast<float>(height) - plot_h - 12.0f * s},
                           {panel - 16.0f * s, plot_h}, text.plot, s);
      });
}

RgbaImage render_before_after_image(GlContext& context, const BeforeAfterPicture& picture, const std::string& title,
                                    const std::vector<std::string>& lines, int width, int height) {
  const PixelViewport world{0, 0, static_cast<float>(width), static_cast<float>(height)};
  return render(
      context, width, height,
      [&](Renderer2D& r) {
        r.set_camera(before_after_camera(picture, world));
        paint_before_after(r, picture);
      },
      [&](ImGuiLayer& imgui) {
        ImDrawList& dl = *ImGui::GetBackgroundDrawList();
        const float s = imgui.scale(), fs = ImGui::GetFontSize();
        const float x = 16.0f * s;
        float y = 12.0f * s;
        const float box_w = 470.0f * s;
        const float box_h = fs * (3.6f + 1.3f * static_cast<float>(lines.size()));
        dl.AddRectFilled({x - 8.0f * s, y - 6.0f * s}, {x + box_w, y + box_h}, IM_COL32(12, 15, 20, 200), 8.0f * s);
        dl.AddText(imgui.fonts().bold, fs, {x, y}, kCaptionText, title.c_str());
        y += fs * 1.4f;
        dl.AddLine({x, y + fs * 0.5f}, {x + fs * 1.6f, y + fs * 0.5f}, to_u32(kBefore), 4.0f * s);
        const std::string before = "before: " + std::to_string(picture.before.size()) +
                                   (picture.before.size() == 1 ? " pre-test trial" : " pre-test trials");
        dl.AddText({x + fs * 2.2f, y}, kCaptionText, before.c_str());
        const std::string after = "after: " + std::to_string(picture.after.size()) +
                                  (picture.after.size() == 1 ? " evaluation trial" : " evaluation trials");
        dl.AddLine({x + box_w * 0.5f, y + fs * 0.5f}, {x + box_w * 0.5f + fs * 1.6f, y + fs * 0.5f}, to_u32(kAfter),
                   4.0f * s);
        dl.AddText({x + box_w * 0.5f + fs * 2.2f, y}, kCaptionText, after.c_str());
        y += fs * 1.3f;
        text_lines(dl, {x, y}, lines, box_w - 16.0f * s);
      });
}

RgbaImage render_hand_image(GlContext& context, const HandOverlay& overlay, const HandImageText& text, int width,
                            int height) {
  return render(
      context, width, height, [](Renderer2D&) {},
      [&](ImGuiLayer& imgui) {
        ImDrawList& dl = *ImGui::GetBackgroundDrawList();
        const float s = imgui.scale(), fs = ImGui::GetFontSize();
        const float x = 16.0f * s, wrap = static_cast<float>(width) - 32.0f * s;
        float y = 14.0f * s;
        dl.AddText(imgui.fonts().bold, fs, {x, y}, kCaptionText, text.title.c_str(), nullptr, wrap);
        y += fs * 1.5f;
        y = text_lines(dl, {x, y}, text.lines, wrap) + 6.0f * s;
        // The legend: what each line is.
        float lx = x;
        for (const auto& [color, width_px, label] :
             {std::tuple{kOverlayLearner, kOverlayLearnerWidth, "the learner's word"},
              std::tuple{kOverlayGuide, kOverlayBandWidth, "the guide"},
              std::tuple{kOverlayHand, kOverlayBandWidth, "the hand"}}) {
          dl.AddLine({lx, y + fs * 0.5f}, {lx + fs * 1.6f, y + fs * 0.5f}, color, width_px * s);
          dl.AddText({lx + fs * 2.1f, y}, kCaptionText, label);
          lx += fs * 2.1f + ImGui::CalcTextSize(label).x + fs * 1.6f;
        }
        y += fs * 1.6f;
        const float box_h = (static_cast<float>(height) - y - 16.0f * s) * 0.5f - fs * 1.4f;
        const ImVec2 box(wrap, std::max(box_h, 40.0f * s));
        dl.AddText(imgui.fonts().bold, fs, {x, y}, kCaptionText, text.guide_caption.c_str());
        const ImVec2 first(x, y + fs * 1.3f);
        y = first.y + box.y + 8.0f * s;
        dl.AddText(imgui.fonts().bold, fs, {x, y}, kCaptionText, text.hand_caption.c_str());
        draw_hand_overlay(dl, first, {x, y + fs * 1.3f}, box, overlay);
      });
}

RgbaImage render_places_image(GlContext& context, const std::vector<PlacePicture>& places, const std::string& title,
                              const std::vector<std::string>& lines, int width, int height) {
  return render(
      context, width, height, [](Renderer2D&) {},
      [&](ImGuiLayer& imgui) {
        ImDrawList& dl = *ImGui::GetBackgroundDrawList();
        const float s = imgui.scale(), fs = ImGui::GetFontSize();
        const float x = 16.0f * s, wrap = static_cast<float>(width) - 32.0f * s;
        float y = 14.0f * s;
        dl.AddText(imgui.fonts().bold, fs, {x, y}, kCaptionText, title.c_str(), nullptr, wrap);
        y += fs * 1.5f;
        y = text_lines(dl, {x, y}, lines, wrap) + 6.0f * s;
        float lx = x;
        for (const auto& [color, width_px, label] :
             {std::tuple{kOverlayLearner, kOverlayLearnerWidth, "the learner's trial"},
              std::tuple{kOverlayGuide, kOverlayBandWidth, "the expert's, same scenario"},
              std::tuple{kOverlayPart, kOverlayPartWidth, "the part aligned with the expert's skill"}}) {
          dl.AddLine({lx, y + fs * 0.5f}, {lx + fs * 1.6f, y + fs * 0.5f}, color, width_px * s);
          dl.AddText({lx + fs * 2.1f, y}, kCaptionText, label);
          lx += fs * 2.1f + ImGui::CalcTextSize(label).x + fs * 1.6f;
        }
        y += fs * 1.8f;
        const std::size_t count = std::min(places.size(), kMaxPlaces);
        const float gap = 16.0f * s, cell_w = (wrap - gap) * 0.5f;
        const float rows = static_cast<float>((count + 1) / 2);
        const float cell_h = rows > 0 ? (static_cast<float>(height) - y - 12.0f * s) / rows : 0.0f;
        for (std::size_t i = 0; i < count; ++i) {
          const ImVec2 at(x + static_cast<float>(i % 2) * (cell_w + gap), y + static_cast<float>(i / 2) * cell_h);
          dl.AddText(imgui.fonts().bold, fs, at, kCaptionText, places[i].caption.c_str(), nullptr, cell_w);
          const float caption_h =
              imgui.fonts().bold->CalcTextSizeA(fs, 1e9f, cell_w, places[i].caption.c_str()).y + 6.0f * s;
          const ImVec2 box(cell_w, std::max(cell_h - caption_h - gap, 40.0f * s));
          draw_part_overlay(dl, {at.x, at.y + caption_h}, box, places[i].overlay);
        }
      });
}

RgbaImage render_expertise_chart_image(GlContext& context, const ExpertiseChart& chart, const std::string& title,
                                       int width) {
  // Text at the 720-line size whatever the image's height: the height follows the chart, so a scale that followed
  // the height would grow the chart past it. The first frame measures the chart in those fonts.
  const float title_h = 48.0f, margin = 12.0f;
  context.make_current();
  context.resize(width, 720);
  Renderer2D renderer(context);
  ImGuiLayer imgui(context);
  imgui.hold_scale(1.0f);
  imgui.begin_frame(1.0 / 60.0);
  const float chart_width = static_cast<float>(width) - 2 * margin;
  const float chart_height = expertise_chart_height(chart, 1.0f, chart_width, imgui.fonts().bold);
  imgui.end_frame();
  const int height = std::max(720, static_cast<int>(std::ceil(title_h + chart_height + margin)));
  context.resize(width, height);
  for (int frame = 0; frame < 2; ++frame) {
    renderer.begin_frame(kBackground);
    renderer.end_frame();
    imgui.begin_frame(1.0 / 60.0);
    ImDrawList& dl = *ImGui::GetBackgroundDrawList();
    dl.AddText(imgui.fonts().bold, ImGui::GetFontSize() * 1.2f, {16.0f, 12.0f}, kCaptionText, title.c_str());
    draw_expertise_chart(dl, {margin, title_h}, {chart_width, static_cast<float>(height) - title_h - margin}, chart,
                         1.0f, imgui.fonts().bold);
    imgui.end_frame();
  }
  context.present();
  return context.read_rgba();
}

}  // namespace sc::review_view
