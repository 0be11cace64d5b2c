# Sourced by the shell tests: a scratch directory removed on exit, and `bad` to record a failure
# (the script ends with `exit $fail`).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
bad() {
  echo "FAIL $*"
  fail=1
}
