// Stubs for the parts of OpenSees that the three materials link against but never call while
// they are stepped (setTrialStrain, commitState, getStress, getTangent): the interpreter's
// argument parsers (used only by the OPS_* command functions) and LAPACK (used only by
// Matrix::Solve and Invert, reached from sensitivity and response code). Each aborts, so a call
// would be noticed rather than answered wrongly. opserr is a real StandardStream, so warnings
// such as BoucWen's "did not find the root" reach stderr.
#include <OPS_Globals.h>
#include <StandardStream.h>

#include <cstdio>
#include <cstdlib>

namespace {

StandardStream standard_error;

[[noreturn]] void never(const char* what) {
  std::fprintf(stderr, "opensees harness: %s is a stub and was called\n", what);
  std::abort();
}

}  // namespace

OPS_Stream* opserrPtr = &standard_error;

extern "C" {
int OPS_GetNumRemainingInputArgs() { never("OPS_GetNumRemainingInputArgs"); }
int ops_getintinput_(int*, int*) { never("OPS_GetIntInput"); }
int ops_getdoubleinput_(int*, double*) { never("OPS_GetDoubleInput"); }
int dgesv_(int*, int*, double*, int*, int*, double*, int*, int*) { never("dgesv_"); }
int dgetrf_(int*, int*, double*, int*, int*, int*) { never("dgetrf_"); }
int dgetri_(int*, double*, int*, int*, double*, int*, int*) { never("dgetri_"); }
}
