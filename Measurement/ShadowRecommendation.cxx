#include "ShadowRecommendation.h"

#include "ShadowScenes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <map>
#include <ostream>
#include <sstream>

namespace shadowbench
{
namespace
{
const MeasuredCase* Find(const std::vector<MeasuredCase>& cases, const std::string& scene,
  const std::string& setup, const std::string& technique)
{
  for (const MeasuredCase& c : cases)
  {
    if (c.Scene == scene && c.Setup == setup && c.Technique == technique)
    {
      return &c;
    }
  }
  return nullptr;
}

template <typename Key>
void AddOnce(std::vector<Key>& keys, const Key& key)
{
  if (std::find(keys.begin(), keys.end(), key) == keys.end())
  {
    keys.push_back(key);
  }
}

std::string Number(double value, int digits)
{
  std::ostringstream text;
  text << std::fixed << std::setprecision(digits) << value;
  return text.str();
}

// The technique's figures over `setups`, false if it was not measured in one of
// them or its frames have no uniform frame to compare with.
bool Evaluate(const std::vector<MeasuredCase>& cases, const std::string& scene,
  const std::vector<std::string>& setups, const std::string& technique, Candidate& candidate)
{
  double misclassified = 0.0;
  double cost = 0.0;
  for (const std::string& setup : setups)
  {
    const MeasuredCase* mine = Find(cases, scene, setup, technique);
    const MeasuredCase* uniform = Find(cases, scene, setup, "uniform");
    if (!mine || !uniform || !(uniform->Steady > 0.0) || !(uniform->Moving > 0.0) ||
      !std::isfinite(mine->Misclassified) || mine->Counted <= 0)
    {
      return false;
    }
    misclassified += mine->Misclassified;
    cost += std::max(mine->Steady / uniform->Steady, mine->Moving / uniform->Moving);
    candidate.PassClass = mine->PassClass;
    candidate.Resolution = mine->Resolution;
  }
  candidate.Technique = technique;
  candidate.Misclassified = misclassified / static_cast<double>(setups.size());
  candidate.Cost = cost / static_cast<double>(setups.size());
  return std::isfinite(candidate.Cost);
}

bool MoreAccurate(const Candidate& a, const Candidate& b)
{
  return a.Misclassified != b.Misclassified ? a.Misclassified < b.Misclassified : a.Cost < b.Cost;
}

// Misclassified %: small values keep a third decimal, so that two techniques
// that differ are not printed alike.
std::string Percent(double value)
{
  return Number(value, value < 1.0 ? 3 : 2);
}

std::string Figures(const Candidate& c)
{
  return c.Technique + " (" + Percent(c.Misclassified) + "% misclassified, frames " +
    Number(c.Cost, 2) + "x the uniform map's)";
}

std::string Why(const Recommendation& r)
{
  if (!r.HasBest)
  {
    return "no recommendation: the uniform map, the cost's reference, or this module's techniques "
           "have no finite figures over counted pixels in every " + r.LightKind + " set-up";
  }
  std::string why = r.Best.Technique + " is the most accurate within " + Number(r.Budget, 2) +
    "x the uniform map's frame: " + Percent(r.Best.Misclassified) + "% of pixels misclassified, frames " +
    Number(r.Best.Cost, 2) + "x";
  why += r.HasRunnerUp ? "; next " + Figures(r.RunnerUp) : "; no other technique within the budget";
  if (r.HasOverBudget)
  {
    why += "; more accurate but over the budget: " + Figures(r.MostAccurate);
  }
  return why;
}

std::string JSONString(const std::string& text)
{
  std::string quoted = "\"";
  for (const char c : text)
  {
    if (static_cast<unsigned char>(c) < 0x20)
    {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\u%04x", static_cast<unsigned>(c));
      quoted += escaped;
      continue;
    }
    if (c == '"' || c == '\\')
    {
      quoted += '\\';
    }
    quoted += c;
  }
  return quoted + "\"";
}

void WriteCandidateJSON(const Candidate& c, std::ostream& out)
{
  out << "{\"technique\": " << JSONString(c.Technique) << ", \"pass\": " << JSONString(c.PassClass)
      << ", \"map_resolution\": " << c.Resolution << ", \"misclassified\": " << c.Misclassified
      << ", \"cost_to_uniform\": " << c.Cost << "}";
}
} // namespace

std::vector<Recommendation> Recommend(const std::vector<MeasuredCase>& cases, double budget)
{
  std::vector<std::pair<std::string, std::string>> keys; // scene, light kind
  std::map<std::pair<std::string, std::string>, std::vector<std::string>> setups;
  std::vector<std::string> techniques;
  for (const MeasuredCase& c : cases)
  {
    // Sized lights are judged apart: their errors are a penumbra's.
    const std::string kind = shadowscenes::LightKindOfSetup(c.Setup) +
      (shadowscenes::IsSizedLightSetup(c.Setup) ? " (sized)" : "");
    const auto key = std::make_pair(c.Scene, kind);
    AddOnce(keys, key);
    AddOnce(setups[key], c.Setup);
    if (!c.PassClass.empty())
    {
      AddOnce(techniques, c.Technique);
    }
  }
  std::vector<Recommendation> recommendations;
  for (const auto& key : keys)
  {
    Recommendation r;
    r.Scene = key.first;
    r.LightKind = key.second;
    r.Setups = setups[key];
    r.Budget = budget;
    std::vector<Candidate> all;
    for (const std::string& technique : techniques)
    {
      Candidate candidate;
      if (Evaluate(cases, r.Scene, r.Setups, technique, candidate))
      {
        all.push_back(candidate);
      }
    }
    std::sort(all.begin(), all.end(), MoreAccurate);
    std::vector<Candidate> within;
    std::copy_if(all.begin(), all.end(), std::back_inserter(within),
      [budget](const Candidate& c) { return c.Cost <= budget; });
    r.HasBest = !within.empty();
    if (r.HasBest)
    {
      r.Best = within[0];
      r.HasRunnerUp = within.size() > 1;
      if (r.HasRunnerUp)
      {
        r.RunnerUp = within[1];
      }
      r.HasOverBudget = MoreAccurate(all[0], r.Best);
      r.MostAccurate = all[0];
    }
    r.Why = Why(r);
    recommendations.push_back(r);
  }
  return recommendations;
}

void WriteRecommendationsMarkdown(const std::vector<Recommendation>& recommendations, std::ostream& out)
{
  if (recommendations.empty())
  {
    return;
  }
  out << "\n## Recommendation\n\nPer light kind, the most accurate of this module's techniques "
         "(mean misclassified % over the light's set-ups) whose steady and moving frames stay within "
      << Number(recommendations[0].Budget, 2)
      << "x the uniform map's (mean over the set-ups), and the runner-up:\n\n"
         "| scene | light | set-ups | use | pass, map | misclassified % | frame / uniform | runner-up |\n"
         "|---|---|---|---|---|---:|---:|---|\n";
  for (const Recommendation& r : recommendations)
  {
    std::string setups;
    for (const std::string& setup : r.Setups)
    {
      setups += (setups.empty() ? "" : ", ") + setup;
    }
    out << "| " << r.Scene << " | " << r.LightKind << " | " << setups << " | ";
    if (r.HasBest)
    {
      out << r.Best.Technique << " | " << r.Best.PassClass << ", " << r.Best.Resolution << "² | "
          << Percent(r.Best.Misclassified) << " | " << Number(r.Best.Cost, 2) << " | "
          << (r.HasRunnerUp ? Figures(r.RunnerUp) : std::string("-")) << " |\n";
    }
    else
    {
      out << "- | - | - | - | - |\n";
    }
  }
  out << "\n";
  for (const Recommendation& r : recommendations)
  {
    out << "- " << r.Scene << ", " << r.LightKind << ": " << r.Why << ".\n";
  }
}

void WriteRecommendationsJSON(const std::vector<Recommendation>& recommendations, std::ostream& out)
{
  out << "{\n  \"budget\": " << (recommendations.empty() ? 0.0 : recommendations[0].Budget)
      << ",\n  \"metric\": \"misclassified % (mean over the light's set-ups)\",\n"
         "  \"cost\": \"mean over the set-ups of the larger of the steady and moving frame over the "
         "uniform map's\",\n  \"recommendations\": [";
  for (std::size_t i = 0; i < recommendations.size(); ++i)
  {
    const Recommendation& r = recommendations[i];
    out << (i ? ",\n" : "\n") << "    {\"scene\": " << JSONString(r.Scene)
        << ", \"light\": " << JSONString(r.LightKind) << ", \"setups\": [";
    for (std::size_t s = 0; s < r.Setups.size(); ++s)
    {
      out << (s ? ", " : "") << JSONString(r.Setups[s]);
    }
    out << "],\n     \"best\": ";
    if (r.HasBest)
    {
      WriteCandidateJSON(r.Best, out);
    }
    else
    {
      out << "null";
    }
    out << ",\n     \"runner_up\": ";
    if (r.HasRunnerUp)
    {
      WriteCandidateJSON(r.RunnerUp, out);
    }
    else
    {
      out << "null";
    }
    out << ",\n     \"why\": " << JSONString(r.Why) << "}";
  }
  out << "\n  ]\n}\n";
}

} // namespace shadowbench
