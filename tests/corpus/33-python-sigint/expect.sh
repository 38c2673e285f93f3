# 33 (issue 30, finding 10): after the Python module's first write, SIGINT killed the interpreter
# (exit 130) instead of raising KeyboardInterrupt: the output set's cleanup handler replaced Python's
# and was never restored. Now it is installed only while a set holds temporaries and only where the
# disposition is the default (io::OutputSet), so Python's own handler stays. Needs the module (built
# beside the tool); skipped in sanitizer builds (an unsanitised interpreter cannot load it).
module="$(dirname "$bin")/python"
if [[ -d "$module/geartrib" ]] && ! ldd "$bin" 2>/dev/null | grep -q libasan; then
  check python-sigint-after-write 0 "after write_surface: KeyboardInterrupt \(as expected\)" -- env GEARTRIB_PYTHON="$module" timeout 60 /usr/bin/python3 repro.py
  check python-no-temporary-left 0 "still alive; left: \['probe.x3p'\]" -- env GEARTRIB_PYTHON="$module" timeout 60 /usr/bin/python3 repro.py
else
  echo "skip python-sigint (no module at $module, or a sanitizer build)"
fi
