// OSMesa keeps one buffer record per (context, buffer) binding in a global list that it never
// frees (Mesa's gallium OSMesa frontend); LeakSanitizer would fail every test that renders.
// The hooks are read by LSan at start-up in sanitizer builds and are harmless elsewhere.
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\n";
}

// Not "Suppressions used: ... libOSMesa.so" on stderr at every exit: the one suppression is
// this known leak, and a pipeserver's stderr is what l2wall reports (tests compare it exactly).
extern "C" const char* __lsan_default_options();
extern "C" const char* __lsan_default_options() {
  return "print_suppressions=0";
}
