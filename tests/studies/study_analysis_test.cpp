// The study report's statistics on a simulated cohort (study_cohort.hpp) against an independent computation
// written here: the improvements read from the database with this file's own SQL, means and standard errors
// summed by hand, U counted pair by pair, the exact two-sided p-value by enumerating every split of the pooled
// improvements into the two groups, and Holm's step-down done by hand.
#include "teaching/studies/study_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "teaching/records/learner_store.hpp"
#include "teaching/records/sqlite_handle.hpp"
#include "tests/studies/study_cohort.hpp"

namespace sc {
namespace {

using Improvements = std::map<std::string, std::vector<double>>;  // by condition, in enrolment order

Improvements improvements_from_sql(const std::filesystem::path& db_file) {
  records::SqliteDb db(db_file, records::SqliteDb::Mode::ReadOnly);
  auto stmt = db.prepare(
      "SELECT p.condition,"
      " (SELECT avg(score) FROM trials t WHERE t.session_id = s.id AND t.kind = 'pretest'),"
      " (SELECT avg(score) FROM trials t WHERE t.session_id = s.id AND t.kind = 'eval')"
      " FROM study_participants p JOIN sessions s ON s.learner_id = p.learner_id AND s.study_id = p.study_id"
      " WHERE s.finished IS NOT NULL ORDER BY p.seq");
  Improvements out;
  while (stmt.step()) out[stmt.column_text(0)].push_back(stmt.column_double(2) - stmt.column_double(1));
  return out;
}

double pairs_u(const std::vector<double>& a, const std::vector<double>& b) {
  double u = 0.0;
  for (double x : a)
    for (double y : b) u += x > y ? 1.0 : x == y ? 0.5 : 0.0;
  return u;
}

// Two-sided exact p by permutation: every way to pick |a| of the pooled values as group a.
double enumerated_p(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> pooled(a);
  pooled.insert(pooled.end(), b.begin(), b.end());
  const double n1n2 = static_cast<double>(a.size() * b.size());
  const double observed = std::max(pairs_u(a, b), n1n2 - pairs_u(a, b));
  int total = 0, extreme = 0;
  for (unsigned mask = 0; mask < (1u << pooled.size()); ++mask) {
    if (static_cast<std::size_t>(__builtin_popcount(mask)) != a.size()) continue;
    std::vector<double> ga, gb;
    for (std::size_t i = 0; i < pooled.size(); ++i) (mask >> i & 1u ? ga : gb).push_back(pooled[i]);
    ++total;
    extreme += pairs_u(ga, gb) >= observed - 1e-9 ? 1 : 0;
  }
  return std::min(1.0, 2.0 * extreme / total);
}

TEST(StudyAnalysis, SimulatedCohortMatchesAnIndependentComputation) {
  const auto& cohort = test::study_cohort();
  const records::LearnerStore store(cohort.data_dir, records::StoreOptions{.read_only = true});
  const auto study = store.study(test::kCohortStudy);
  ASSERT_TRUE(study);
  const StudyAnalysis a = analyse_study(*study, participant_outcomes(store.study_participants(test::kCohortStudy),
                                                                     store.study_sessions(test::kCohortStudy)));
  const Improvements expected = improvements_from_sql(store.database_path());

  // Participants: 11 enrolled, 9 counted; the unfinished and the never-started are listed with the reason.
  ASSERT_EQ(a.participants.size(), 11u);
  EXPECT_EQ(a.counted(), 9);
  EXPECT_NE(a.participants[9].excluded.find("is unfinished"), std::string::npos) << a.participants[9].excluded;
  EXPECT_EQ(a.participants[10].excluded, "no session yet");

  // Per condition: N, mean, standard error.
  ASSERT_EQ(a.conditions.size(), 3u);
  for (const StudyConditionResult& c : a.conditions) {
    const std::vector<double>& values = expected.count(c.condition) ? expected.at(c.condition) : std::vector<double>{};
    ASSERT_EQ(c.improvement.n, static_cast<int>(values.size())) << c.condition;
    ASSERT_GE(values.size(), 2u) << c.condition << ": the cohort should put 2+ counted participants in each";
    double sum = 0.0;
    for (double v : values) sum += v;
    const double mean = sum / static_cast<double>(values.size());
    double squares = 0.0;
    for (double v : values) squares += (v - mean) * (v - mean);
    const double se = std::sqrt(squares / static_cast<double>(values.size() - 1) / static_cast<double>(values.size()));
    EXPECT_NEAR(c.improvement.mean, mean, 1e-12) << c.condition;
    EXPECT_NEAR(c.improvement.se, se, 1e-12) << c.condition;
    EXPECT_EQ(c.improvements, values) << c.condition;
  }

  // The paper's three pairs, U and exact p each, then Holm over the three.
  ASSERT_EQ(a.comparisons.size(), 3u);
  std::vector<double> p;
  for (const StudyConditionComparison& c : a.comparisons) {
    ASSERT_TRUE(c.test) << c.a << " vs " << c.b;
    const auto& xa = expected.at(c.a);
    const auto& xb = expected.at(c.b);
    EXPECT_EQ(c.test->method, stats::MannWhitneyMethod::Exact);  // no ties, at most 8 per condition
    EXPECT_DOUBLE_EQ(c.test->u, pairs_u(xa, xb)) << c.a << " vs " << c.b;
    EXPECT_NEAR(c.test->p, enumerated_p(xa, xb), 1e-12) << c.a << " vs " << c.b;
    p.push_back(enumerated_p(xa, xb));
  }
  std::vector<std::size_t> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
  double running = 0.0;
  for (std::size_t rank = 0; rank < 3; ++rank) {
    running = std::max(running, std::min(1.0, static_cast<double>(3 - rank) * p[order[rank]]));
    EXPECT_NEAR(a.comparisons[order[rank]].p_holm, running, 1e-12);
  }
  EXPECT_EQ(a.comparisons[0].a, "skills");
  EXPECT_EQ(a.comparisons[0].b, "full-trajectory");
}

}  // namespace
}  // namespace sc
