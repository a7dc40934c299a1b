// Default sanitizer options of the LENSLAB_SANITIZE build, linked into each of its executables
// (top-level CMakeLists.txt), so that ctest, tools/sanitize.sh and a `lenslab` run by hand behave
// the same. ASAN_OPTIONS, UBSAN_OPTIONS and LSAN_OPTIONS in the environment are applied after
// these, so they add to or override them; the environment's LSAN_OPTIONS=suppressions=FILE adds
// to the suppressions below.

extern "C" {

// Findings abort (a core-dump-free SIGABRT, so ctest shows the test as failed with the report).
// intercept_tls_get_addr=0: the sanitizer's tracking of dynamic TLS (blocks glibc hands out through
// __tls_get_addr to dlopen'ed libraries: Mesa's driver, LLVM) recorded a bogus range in some runs
// ("DTLS 40 at 0x000000003465-0x001800004567" with LSAN_OPTIONS=verbosity=1), and LeakSanitizer's
// exit-time tracer then died reading it ("Tracer caught signal 11 ... LeakSanitizer has encountered
// a fatal error"): `render --camera assets/occluder/camera-dof.json --pattern random --stats ...`
// did so on every run, depending on the heap's layout. Untracked, those blocks are not scanned for
// pointers; our code is linked in, not dlopen'ed, so its static TLS is scanned as before, and the
// unit and cli tests report no leak either way.
const char* __asan_default_options() {
  return "abort_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1:intercept_tls_get_addr=0";
}

// UBSan: a stack trace, and stop at the first finding (with -fno-sanitize-recover=undefined the
// process aborts whatever this says; kept for builds that recover).
const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

// LeakSanitizer stays on, for our code and for Mesa's. One suppression, for OSMesa, which lenslab
// opens with dlopen (src/gl/OsmesaContext.cpp): OSMesaMakeCurrent allocates buffer records
// (5 blocks, 480 bytes a process) that OSMesaDestroyContext does not free; a leak whose stack
// passes through libOSMesa.so is Mesa's. Measured over the unit, cli and gl tests (LSAN_OPTIONS=
// print_suppressions=1): nothing else is suppressed, and no other leak is reported (EGL included,
// with dlclose below).
const char* __lsan_default_suppressions() { return "leak:libOSMesa.so\n"; }

// Without print_suppressions=0 a suppressed leak adds a table to stderr at exit, which the CLI
// tests would count as more than one line of error.
const char* __lsan_default_options() { return "print_suppressions=0"; }

// Libraries opened with dlopen stay loaded until the process ends. libglvnd unloads Mesa's EGL
// vendor library (and Mesa its driver) before exit; LeakSanitizer, which runs at exit, can then no
// longer scan their globals, and reported the blocks those held as leaks from "<unknown module>"
// (2 x 56 bytes in each EGL run and each GL run ending in an error), which no suppression can name.
// This definition takes the place of libc's dlclose for every library in the process (the
// executable's symbols come first); it exists only in the sanitizer build.
int dlclose(void*) { return 0; }

}  // extern "C"
