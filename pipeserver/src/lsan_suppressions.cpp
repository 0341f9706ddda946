// OSMesa keeps one buffer record per (context, buffer) binding in a global list that it never
// frees (Mesa's gallium OSMesa frontend); LeakSanitizer would fail every test that renders.
// The hook is read by LSan at start-up in sanitizer builds and is harmless elsewhere.
extern "C" const char* __lsan_default_suppressions();
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\n";
}
