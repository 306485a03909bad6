# Sourced by the command-line tests: `expect STATUS PATTERN -- ARGS...` runs "$bin" ARGS,
# checks its exit status and that its output holds PATTERN, and sets fail=1 when not.
fail=0

expect() {
  local want=$1 pattern=$2
  shift 3
  local out status
  out=$("$bin" "$@" 2>&1)
  status=$?
  if [ "$status" -ne "$want" ]; then
    echo "FAIL: csmhair $* exited $status, expected $want"; echo "$out"; fail=1
  elif ! grep -qF -- "$pattern" <<<"$out"; then
    echo "FAIL: csmhair $*: output lacks '$pattern'"; echo "$out"; fail=1
  else
    echo "ok: csmhair $* -> $status: $(head -n1 <<<"$out")"
  fi
}
