#include "app/gui/screens/review_model.hpp"

#include "app/gui/screens/learn_flow.hpp"
#include "engine/core/error.hpp"
#include "teaching/records/data_dir.hpp"
#include "teaching/records/open_record_store.hpp"
#include "teaching/review/practice_rounds.hpp"

namespace sc {

ReviewModel::ReviewModel(AppServices& services) : services_(services) {
  if (services.headless) {
    // The trainer's screenshot session (fixed seed, timestamps and scripted learner) up to its summary.
    learn_flow_for_screenshot(services, SessionPhase::Summary);
  }
  reload();
  if (!rows_.empty()) select_session(rows_.front().session_id);
}

void ReviewModel::reload() {
  try {
    const std::filesystem::path dir = services_.options.data_dir.empty()
                                          ? records::default_data_dir()
                                          : std::filesystem::path(services_.options.data_dir);
    const records::StoreOptions read_only{.read_only = true};
    store_ = services_.options.store.empty() ? std::make_unique<records::LearnerStore>(dir, read_only)
                                             : records::open_record_store(services_.options.store, read_only);
    rows_ = review::session_rows(store_->list_learners());
    message.clear();
  } catch (const InputError& e) {
    message = e.what();
    rows_.clear();
  }
}

review::SessionFilter ReviewModel::filter() const {
  static constexpr const char* kTasks[] = {"", "parking", "writing"};
  return {filter_fields.learner.data(), kTasks[filter_fields.task], filter_fields.from.data(), filter_fields.to.data()};
}

void ReviewModel::sort(review::SessionColumn column, bool ascending) {
  review::sort_session_rows(rows_, column, ascending);
}

const review::SessionListRow* ReviewModel::session_row() const {
  if (!session_) return nullptr;
  for (const auto& row : rows_)
    if (row.session_id == session_->record().session.id) return &row;
  return nullptr;
}

void ReviewModel::select_session(std::int64_t id) {
  if (!store_) return;
  try {
    review::SessionRecord record = review::load_session_record(*store_, id);
    session_ = std::make_unique<review::SessionReview>(kits_.kit_of(record.session), std::move(record));
    rounds_.reset();
    rounds_problem_.clear();
    try {
      rounds_ = review::expertise_rounds(session_->kit(), session_->record());
    } catch (const InputError& e) {
      rounds_problem_ = e.what();
    }
    palette_ = rounds_ ? session_palette(*rounds_) : review_view::SkillPalette{};
    trial_.reset();
    groups_.reset();
    test_trials_.reset();
    group_pictures_.clear();
    chart_.reset();
    diagnosis_.reset();
    diagnosis_tried_ = false;
    place_pictures_.clear();
    skill_pictures_.clear();
    diagnosis_problem.clear();
    practice_lines_.reset();
    if (!session_->record().trials.empty()) select_trial(session_->record().trials.front().seq);
  } catch (const InputError& e) {
    message = e.what();
  }
}

void ReviewModel::select_trial(int seq) {
  if (!session_) return;
  try {
    trial_ = session_->trial(seq);
    picture_ = trial_picture(*trial_, palette_);
    playback_.load(trial_->learner_track.steps(), trial_->learner_track.step_seconds);
  } catch (const InputError& e) {
    message = e.what();
  }
}

const std::vector<review::TrialReview>& ReviewModel::test_trials() {
  if (!test_trials_) {
    test_trials_.emplace();
    for (const auto& t : session_->record().trials)
      if (t.record.kind == records::TrialKind::Pretest || t.record.kind == records::TrialKind::Eval)
        test_trials_->push_back(session_->trial(t.seq));
  }
  return *test_trials_;
}

const std::vector<review::BeforeAfterGroup>& ReviewModel::before_after_groups() {
  if (!groups_) {
    groups_.emplace();
    if (session_) {
      try {
        *groups_ = review::before_after_groups(session_->record());
      } catch (const InputError& e) {
        message = e.what();
      }
    }
  }
  return *groups_;
}

const review_view::BeforeAfterPicture& ReviewModel::before_after_picture(std::size_t group) {
  auto it = group_pictures_.find(group);
  if (it == group_pictures_.end())
    it = group_pictures_.emplace(group, sc::before_after_picture(before_after_groups().at(group), test_trials())).first;
  return it->second;
}

std::vector<std::string> ReviewModel::before_after_lines(std::size_t group) {
  return sc::before_after_lines(before_after_groups().at(group), test_trials());
}

const review_view::ExpertiseChart* ReviewModel::expertise_chart() {
  if (!chart_ && session_) {
    if (rounds_) {
      chart_ = sc::expertise_chart(*rounds_, palette_);
    } else {
      message = rounds_problem_;
      chart_.emplace();
    }
  }
  return chart_ ? &*chart_ : nullptr;
}

const review::DiagnosisExplanation* ReviewModel::diagnosis() {
  if (!diagnosis_tried_ && session_) {
    diagnosis_tried_ = true;
    try {
      diagnosis_ = review::explain_diagnosis(*session_);
    } catch (const InputError& e) {
      diagnosis_problem = e.what();
    }
  }
  return diagnosis_ ? &*diagnosis_ : nullptr;
}

const SkillPictureData* ReviewModel::skill_picture(int skill) {
  if (!session_) return nullptr;
  auto found = skill_pictures_.find(skill);
  if (found == skill_pictures_.end()) {
    found = skill_pictures_.emplace(skill, skill_example_picture(session_->kit().expert_pool(), skill)).first;
  }
  return found->second ? &*found->second : nullptr;
}

const TrialPartPictureData* ReviewModel::place_picture(int skill) {
  if (const auto found = place_pictures_.find(skill); found != place_pictures_.end()) return &found->second;
  const review::DiagnosisExplanation* d = diagnosis();
  if (!d) return nullptr;
  for (const review::SkillExplanation& s : d->skills)
    if (s.skill == skill && s.place)
      return &place_pictures_.emplace(skill, trial_part_picture_data(*s.place)).first->second;
  return nullptr;
}

const std::vector<std::string>& ReviewModel::practice_lines() {
  if (!practice_lines_) {
    practice_lines_.emplace();
    if (session_) {
      try {
        for (const auto& round : review::practice_rounds(session_->record()))
          practice_lines_->push_back(review::practice_round_text(round));
      } catch (const InputError& e) {
        practice_lines_->push_back(e.what());
      }
    }
  }
  return *practice_lines_;
}

}  // namespace sc
