// ThreadSanitizer's suppressions for viewer_tests (added to it in a -DRADMESH_TSAN=ON build).
// llvmpipe's worker threads synchronise inside Mesa, which is not instrumented, so TSan
// reports races between Mesa's own threads (a fence's mutex destroyed after its worker's last
// broadcast). Reports from inside libOSMesa are not ours; everything of radmesh's stays checked
// (SolverThread.* run the solver thread against the UI's reads).
#if defined(__SANITIZE_THREAD__)
extern "C" const char* __tsan_default_suppressions() { return "called_from_lib:libOSMesa.so.8\n"; }
#endif
