// The trainer's first page: who is learning (a new name or a returning learner), an offer to resume an
// unfinished session, and — hidden behind Ctrl+Shift+R — research mode, which picks the study condition so
// the paper's study can be rerun with real people. Task and device come from the start screen.
#include <imgui.h>

#include <array>
#include <cstring>
#include <memory>
#include <string>

#include "app/gui/navigator.hpp"
#include "app/gui/screen.hpp"
#include "app/gui/screens/learn_flow.hpp"
#include "app/gui/screens/learn_ui.hpp"
#include "engine/core/error.hpp"
#include "teaching/records/data_dir.hpp"

namespace sc {
namespace {

class LearnWelcomeScreen final : public Screen {
 public:
  explicit LearnWelcomeScreen(AppServices& services) : services_(services), flow_(learn_flow(services)) {
    if (services.headless && flow_.learner.empty()) {
      // Screenshots: a returning learner in a fresh temporary database, nothing unfinished.
      flow_.learner = "Ada";
      flow_.headless_clock = true;
      services.options.data_dir = (std::filesystem::temp_directory_path() / "skillcoach-screenshot-welcome").string();
      std::filesystem::remove_all(services.options.data_dir);
      flow_.store(services).ensure_learner("Ada", "2024-05-01T12:00:00.000Z");
    }
    std::strncpy(name_.data(), flow_.learner.c_str(), name_.size() - 1);
  }

  void update(const FrameInput& input, double) override {
    const bool ctrl = input.keys_down[SDL_SCANCODE_LCTRL] || input.keys_down[SDL_SCANCODE_RCTRL];
    const bool shift = input.keys_down[SDL_SCANCODE_LSHIFT] || input.keys_down[SDL_SCANCODE_RSHIFT];
    if (ctrl && shift && input.keys_pressed[SDL_SCANCODE_R]) flow_.research = !flow_.research;
    confirm_ = confirm_ || learn_ui::confirm_pressed(input);
  }

  void draw(UiContext& ui) override {
    learn_ui::begin_card(ui, "learn_welcome", 640.0f);
    learn_ui::title(ui, services_.task == TaskKind::parking ? "Parking trainer" : "Writing trainer");
    learn_ui::muted_wrapped(
        "A short test shows what you can already do. SkillCoach then picks practice drills for the skills you "
        "need most, and a final test shows how far you came.");
    ImGui::Dummy(ImVec2(0, 8 * ui.ui_scale));
    draw_name(ui);
    draw_learners(ui);
    draw_round_size(ui);
    if (flow_.research) draw_research(ui);
    ImGui::Dummy(ImVec2(0, 8 * ui.ui_scale));
    draw_start(ui);
    if (server_unreachable()) {
      draw_offline_choice();
    } else if (!flow_.message.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.5f, 1.0f));
      ImGui::TextWrapped("%s", flow_.message.c_str());
      ImGui::PopStyleColor();
    }
    if (offline_)
      learn_ui::muted_wrapped(("Training on this computer: your records are kept in " + data_dir() + ".").c_str());
    ImGui::Dummy(ImVec2(0, 4 * ui.ui_scale));
    ImGui::TextDisabled("Device: %s", describe(services_.device).c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("Change task or device")) ui.navigator.go_to("start");
    learn_ui::end_card();
  }

 private:
  void draw_name(UiContext& ui) {
    learn_ui::heading(ui, "Your name");
    ImGui::SetNextItemWidth(-1);
    // The field has the keyboard from the start (no click before typing), and Enter in it continues.
    if (!name_focused_) ImGui::SetKeyboardFocusHere();
    name_focused_ = true;
    const bool entered = ImGui::InputText("##name", name_.data(), name_.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    if (ImGui::IsItemEdited() || entered) flow_.learner = name_.data();
    confirm_ = confirm_ || entered;
  }

  void draw_learners(UiContext& ui) {
    std::vector<records::LearnerOverview> learners;
    try {
      learners = flow_.store(services_).list_learners();
    } catch (const InputError& e) {
      flow_.message = e.what();
      return;
    }
    if (learners.empty()) return;
    ImGui::TextDisabled("Returning? Pick your name:");
    for (const auto& l : learners) {
      ImGui::SameLine();
      if (ImGui::SmallButton(l.name.c_str())) {
        flow_.learner = l.name;
        std::strncpy(name_.data(), l.name.c_str(), name_.size() - 1);
      }
    }
    (void)ui;
  }

  // Closed by default: the defaults (3 skills x 2 drills, a few minutes) suit a first session.
  void draw_round_size(UiContext& ui) {
    ImGui::Dummy(ImVec2(0, 4 * ui.ui_scale));
    const std::string label = "Practice per round: " + std::to_string(flow_.drills_per_weak_skill) +
                              " drills for each of your " + std::to_string(flow_.weak_skills) +
                              " weakest skills###round_size";
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    const bool open = ImGui::TreeNode(label.c_str());
    ImGui::PopStyleColor();
    if (!open) return;
    ImGui::SetNextItemWidth(220 * ui.ui_scale);
    ImGui::SliderInt("weakest skills", &flow_.weak_skills, 1, 5);
    ImGui::SetNextItemWidth(220 * ui.ui_scale);
    ImGui::SliderInt("drills per skill", &flow_.drills_per_weak_skill, 1, 5);
    learn_ui::muted_wrapped("Each drill is a demonstration, then your turn. Saved with the session.");
    ImGui::TreePop();
  }

  // The studies of this task in the database: joining one enrols the learner, whose condition the study's
  // randomisation assigns and no screen shows. Without a study the condition is chosen here.
  void draw_studies(UiContext& ui) {
    std::vector<records::StudyDefinition> studies;
    try {
      studies = flow_.store(services_).list_studies();
    } catch (const InputError& e) {
      flow_.message = e.what();
    }
    std::erase_if(studies, [&](const auto& s) { return s.task != to_string(services_.task); });
    if (studies.empty()) {
      flow_.study.clear();
      return;
    }
    learn_ui::heading(ui, "Research mode: study");
    if (ImGui::RadioButton("No study (choose the condition)", flow_.study.empty())) flow_.study.clear();
    for (const auto& study : studies) {
      const auto enrolled = flow_.store(services_).study_participants(study.name).size();
      const std::string label =
          study.name + " (" + std::to_string(enrolled) + " of " + std::to_string(study.capacity()) + " enrolled)";
      if (ImGui::RadioButton(label.c_str(), flow_.study == study.name)) flow_.study = study.name;
    }
  }

  void draw_research(UiContext& ui) {
    ImGui::Separator();
    draw_studies(ui);
    if (!flow_.study.empty()) {
      learn_ui::muted_wrapped("The study assigns the condition when the learner starts; it is not shown.");
    } else {
      draw_conditions(ui);
    }
    draw_lot(ui);
  }

  void draw_conditions(UiContext& ui) {
    learn_ui::heading(ui, "Research mode: study condition");
    for (StudyCondition c : kAllStudyConditions) {
      const std::string label(condition_name(c));
      if (ImGui::RadioButton(label.c_str(), flow_.condition == c)) flow_.condition = c;
      if (c != StudyCondition::Drills && c != StudyCondition::Adaptive) ImGui::SameLine();
    }
  }

  void draw_lot(UiContext& ui) {
    if (services_.task != TaskKind::parking) return;
    learn_ui::heading(ui, "Research mode: goal spots");
    if (ImGui::RadioButton("Study corner (spots 12-14, the paper's study)",
                           flow_.research_lot == GoalRegion::StudyCorner))
      flow_.research_lot = GoalRegion::StudyCorner;
    ImGui::SameLine();
    if (ImGui::RadioButton("Whole lot", flow_.research_lot == GoalRegion::WholeLot))
      flow_.research_lot = GoalRegion::WholeLot;
  }

  void draw_start(UiContext& ui) {
    const bool named = !flow_.learner.empty();
    std::optional<records::ResumePoint> unfinished;
    try {
      if (named) unfinished = flow_.unfinished(services_);
    } catch (const InputError& e) {
      flow_.message = e.what();
    }
    ImGui::BeginDisabled(!named);
    if (unfinished) {
      const auto& p = unfinished->session.progress;
      ImGui::TextWrapped("Welcome back. Your last session stopped in round %d at %s (%d trials kept).", p.round,
                         std::string(records::to_string(p.phase)).c_str(), unfinished->trials_done);
      if (learn_ui::primary_button(ui, "Resume where I stopped") || (confirm_ && named)) begin(ui, true);
      if (ImGui::Button("Start a new session", ImVec2(-1, 0))) begin(ui, false);
    } else if (learn_ui::primary_button(ui, "Continue") || (confirm_ && named)) {
      begin(ui, false);
    }
    ImGui::EndDisabled();
    confirm_ = false;
  }

  std::string data_dir() const {
    return services_.options.data_dir.empty() ? records::default_data_dir().string() : services_.options.data_dir;
  }
  bool server_unreachable() const { return !services_.options.store.empty() && flow_.store_failed(); }

  // A class server that cannot be reached: say what it means and offer this computer's own store (the
  // technical reason on hover, so the page keeps its layout whatever the error says). The server is what keeps a
  // learner on one desktop at a time, so a session cannot start on it offline; records kept here move to the class
  // store later (export, import) as sessions of their own.
  void draw_offline_choice() {
    ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.5f, 1.0f), "The class server cannot be reached.");
    ImGui::SameLine();
    ImGui::TextDisabled("(details)");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", flow_.message.c_str());
    if (ImGui::Button("Train on this computer", ImVec2(-1, 0))) {
      services_.options.store.clear();
      flow_.retry_store();
      flow_.message.clear();
      offline_ = true;
      return;
    }
    learn_ui::muted_wrapped(
        "Press Continue to try again, or train on this computer: your records stay in its data directory until "
        "your instructor moves them to the class store (skillcoach export, then import).");
  }

  void begin(UiContext& ui, bool resume) {
    try {
      flow_.retry_store();
      flow_.message.clear();
      flow_.start(services_, resume);
      TrainingSession& s = *flow_.session();
      const bool fresh = s.phase() == SessionPhase::Pretest && s.item_index() == 0;
      ui.navigator.go_to(fresh ? "learn_instructions" : screen_for_phase(s.phase()));
    } catch (const InputError& e) {
      flow_.message = e.what();
    }
  }

  AppServices& services_;
  LearnFlow& flow_;
  std::array<char, 64> name_{};
  bool confirm_ = false;
  bool name_focused_ = false;
  bool offline_ = false;  // the learner chose this computer's store over an unreachable class server
};

const ScreenRegistration kLearnWelcomeScreenRegistration{
    {"learn_welcome", "Trainer: welcome, learner name, resume",
     [](AppServices& services) { return std::make_unique<LearnWelcomeScreen>(services); }}};

}  // namespace
}  // namespace sc
