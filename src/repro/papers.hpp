#pragma once
// The papers `zcube reproduce` knows: a name (the command's argument and the results/ folder), the
// names docs/index.md also gives it, one line on what it reproduces, and the plan that does it
// (reproduce_<paper>.cpp). A new paper is its folder in src/algo/, its reproduce_<paper>.cpp and
// one line in papers.cpp.
#include <string>
#include <vector>

#include "repro/reproduce.hpp"

namespace zc {

struct Paper {
  std::string name;
  std::vector<std::string> aliases;
  std::string description;
  PaperPlan (*plan)(const ReproduceOptions&);
};

// Every paper, in the order reproduce runs and lists them.
const std::vector<Paper>& papers();
// The paper a name or alias designates; nullptr for none.
const Paper* find_paper(const std::string& name);
// Every name and alias, for the command line's choices.
std::vector<std::string> paper_names_and_aliases();
// "kurc, charles, blazek, compositing": the names, for messages.
std::string paper_names_text();
// One line a paper, "name (aliases): description", for the command's help.
std::string papers_help();

} // namespace zc
