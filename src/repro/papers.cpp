#include "repro/papers.hpp"

namespace zc {

const std::vector<Paper>& papers() {
  static const std::vector<Paper> p = {
      {"kurc", {}, "Kurc, Aykanat, Ozguc: Table 2 and the merging schemes' speed-ups", kurc_plan},
      {"charles",
       {"charles95"},
       "Charles, Lefevre, Miguet 1995: the elastic z-buffer's speed-ups and Table 1",
       charles_plan},
      {"blazek", {"blazek91"}, "Blazek 1991: the four decompositions' speed-ups", blazek_plan},
      {"compositing",
       {},
       "the compositing strategies on the three papers' machines",
       compositing_plan},
  };
  return p;
}

const Paper* find_paper(const std::string& name) {
  for (const auto& p : papers()) {
    if (p.name == name) return &p;
    for (const auto& a : p.aliases)
      if (a == name) return &p;
  }
  return nullptr;
}

std::vector<std::string> paper_names_and_aliases() {
  std::vector<std::string> v;
  for (const auto& p : papers()) {
    v.push_back(p.name);
    v.insert(v.end(), p.aliases.begin(), p.aliases.end());
  }
  return v;
}

std::string paper_names_text() {
  std::string s;
  for (const auto& p : papers())
    s += (s.empty() ? "" : ", ") + p.name;
  return s;
}

std::string papers_help() {
  std::string s;
  for (const auto& p : papers()) {
    s += "\n  " + p.name;
    for (const auto& a : p.aliases)
      s += (&a == &p.aliases.front() ? " (" : ", ") + a;
    s += std::string(p.aliases.empty() ? "" : ")") + ": " + p.description;
  }
  return s;
}

} // namespace zc
