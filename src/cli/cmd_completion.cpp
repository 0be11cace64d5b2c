// zcube completion bash: a bash completion script. The words come from zcube itself when a word is
// completed (the commands from `zcube --help`, a command's flags from its own --help, which CLI11
// makes from the flag table), so the script never falls behind the binary.
#include <iostream>

#include "cli/command.hpp"
#include "cli/parse.hpp"

namespace zc::cli {

static const char* const kBashCompletion = R"(# bash completion for zcube (zcube completion bash)
_zcube() {
  local cur=${COMP_WORDS[COMP_CWORD]} words
  if [ "$COMP_CWORD" -eq 1 ]; then
    words="$("${COMP_WORDS[0]}" --help 2>/dev/null | awk '/^  [a-z]/ {print $1}') help"
  elif [ "${COMP_WORDS[1]}" = help ] && [ "$COMP_CWORD" -eq 2 ]; then
    words="$("${COMP_WORDS[0]}" --help 2>/dev/null | awk '/^  [a-z]/ {print $1}') flags"
  else
    case $cur in
    -*) words=$("${COMP_WORDS[0]}" "${COMP_WORDS[1]}" --help 2>/dev/null |
      grep -o -- '--[a-z][a-z0-9-]*' | sort -u) ;;
    *) COMPREPLY=(); return 0 ;; # files: bash's own completion (-o default)
    esac
  fi
  COMPREPLY=($(compgen -W "$words" -- "$cur"))
}
complete -o default -F _zcube zcube
)";

static int cmd_completion(std::vector<std::string> args) {
  CLI::App app{"Print a shell completion script (bash): "
               "source <(zcube completion bash), or install it as "
               "/usr/share/bash-completion/completions/zcube",
               "zcube completion"};
  std::string shell = "bash";
  app.add_option("shell", shell, "the shell")
      ->check(CLI::IsMember({"bash"}))
      ->capture_default_str();
  if (int rc = parse(app, args); rc >= 0) return rc;
  std::cout << kBashCompletion;
  return 0;
}

ZC_COMMAND("completion", "print a bash completion script", cmd_completion);

} // namespace zc::cli
