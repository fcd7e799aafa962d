// Which technique to use, from a benchmark's figures: for each scene and light
// kind, the most accurate of this module's techniques whose frames stay within
// a budget of the uniform map's, the runner-up, and why (vtkshadows analyze and
// bench). Pure: no VTK.
#ifndef ShadowRecommendation_h
#define ShadowRecommendation_h

#include <iosfwd>
#include <string>
#include <vector>

namespace shadowbench
{

/// One measured case as the recommendation reads it.
struct MeasuredCase
{
  std::string Scene;
  std::string Setup; // a light set-up (shadowscenes::LightSetupNames)
  std::string Technique;
  std::string PassClass; // empty for no shadows and VTK's pass
  int Resolution = 0;    // of the technique's maps
  double Misclassified = 0.0; // % of counted pixels
  double Steady = 0.0;        // seconds per frame
  double Moving = 0.0;
  long long Counted = 0; // pixels the error is of; 0: not measured
};

/// A technique's figures over the set-ups of one light kind.
struct Candidate
{
  std::string Technique;
  std::string PassClass;
  int Resolution = 0;
  double Misclassified = 0.0; // mean over the set-ups, %
  double Cost = 0.0; // mean over the set-ups of the larger of its steady and moving frame over the uniform map's
};

struct Recommendation
{
  std::string Scene;
  std::string LightKind; // "sun", "spot" or "point"
  std::vector<std::string> Setups;
  double Budget = 0.0;
  bool HasBest = false;
  Candidate Best;
  bool HasRunnerUp = false;
  Candidate RunnerUp;
  /// The most accurate candidate where it is over the budget (else HasBest's).
  bool HasOverBudget = false;
  Candidate MostAccurate;
  std::string Why; // one line
};

/**
 * For each scene and light kind in `cases` (in their order): this module's
 * techniques (a PassClass) measured in every set-up of that kind (finite
 * figures over counted pixels), ranked by
 * their mean misclassified % (then by cost) among those whose Cost is at most
 * `budget`. The uniform map is the cost's reference: without it in every
 * set-up of a kind, that kind gets no best (Why says so).
 */
std::vector<Recommendation> Recommend(const std::vector<MeasuredCase>& cases, double budget);

/// A markdown section: a table row per scene and light kind, and the why lines.
void WriteRecommendationsMarkdown(const std::vector<Recommendation>& recommendations, std::ostream& out);

/// The same as JSON: {"budget": ..., "recommendations": [...]}.
void WriteRecommendationsJSON(const std::vector<Recommendation>& recommendations, std::ostream& out);

} // namespace shadowbench

#endif
