/* hawser's MoorDyn-compatible library (libmoordyn from crates/hawser-moordyn): declarations
 * of the coupling subset of MoorDyn v2's C API that it exports, with MoorDyn's names and
 * signatures, so that a host written against MoorDyn builds and links against hawser.
 * docs/c-api.md lists the functions and what differs from MoorDyn's library. */
#ifndef HAWSER_MOORDYN2_H
#define HAWSER_MOORDYN2_H

#ifdef __cplusplus
extern "C" {
#endif

/* Status codes (MoorDyn's values). */
#define MOORDYN_SUCCESS 0
#define MOORDYN_INVALID_INPUT_FILE -1
#define MOORDYN_INVALID_OUTPUT_FILE -2
#define MOORDYN_INVALID_INPUT -3
#define MOORDYN_NAN_ERROR -4
#define MOORDYN_MEM_ERROR -5
#define MOORDYN_INVALID_VALUE -6
#define MOORDYN_NON_IMPLEMENTED -7
#define MOORDYN_UNHANDLED_ERROR -255

/* A mooring system; a line of it. */
typedef struct __MoorDyn* MoorDyn;
typedef struct __MoorDynLine* MoorDynLine;

MoorDyn MoorDyn_Create(const char* infilename);
int MoorDyn_NCoupledDOF(MoorDyn system, unsigned int* n);
int MoorDyn_Init(MoorDyn system, const double* x, const double* xd);
int MoorDyn_Step(MoorDyn system, const double* x, const double* xd, double* f, double* t,
                 double* dt);
int MoorDyn_Close(MoorDyn system);
int MoorDyn_GetNumberLines(MoorDyn system, unsigned int* n);
MoorDynLine MoorDyn_GetLine(MoorDyn system, unsigned int l);
int MoorDyn_GetFASTtens(MoorDyn system, const int* numLines, float FairHTen[],
                        float FairVTen[], float AnchHTen[], float AnchVTen[]);
int MoorDyn_SaveState(MoorDyn system, const char* filepath);
int MoorDyn_LoadState(MoorDyn system, const char* filepath);

int MoorDyn_GetLineID(MoorDynLine l, int* id);
int MoorDyn_GetLineN(MoorDynLine l, unsigned int* n);
int MoorDyn_GetLineNumberNodes(MoorDynLine l, unsigned int* n);
int MoorDyn_GetLineNodePos(MoorDynLine l, unsigned int i, double pos[3]);
int MoorDyn_GetLineNodeTen(MoorDynLine l, unsigned int i, double t[3]);
int MoorDyn_GetLineNodeForce(MoorDynLine l, unsigned int i, double f[3]);
int MoorDyn_GetLineFairTen(MoorDynLine l, double* t);

#ifdef __cplusplus
}
#endif
#endif
