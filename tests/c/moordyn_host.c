/* A coupling host written against MoorDyn v2's C API (MoorDyn2.h): the OC3 deck's three
 * fairleads in a surge x = x0 + A sin(2 pi t / T), coupled every dtc seconds with MoorDyn's
 * convention (x at the start of each interval, xd the forward difference to the next sample,
 * so that the fairleads follow the piecewise-linear interpolant of the samples).
 *
 *   moordyn_host DECK DURATION DTC EVERY [STATE_FILE]
 *
 * Prints a CSV row every EVERY intervals: t, then per line |Fnet| of the fairlead node
 * (FairTen), then the coupled forces f. With STATE_FILE, it also saves the state half-way,
 * runs on, loads it back and checks that the second half repeats to the last bit. Built
 * against MoorDyn's own library or hawser's libmoordyn, unchanged. */
#include "MoorDyn2.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define A 2.0
#define T 10.0
#define MAXDOF 64
#define MAXLINES 16

static double surge(double t) { return A * sin(2.0 * M_PI * t / T); }

static int check(int err, const char* what)
{
	if (err != MOORDYN_SUCCESS) {
		fprintf(stderr, "moordyn_host: %s failed with %d\n", what, err);
		exit(1);
	}
	return err;
}

/* Runs intervals k0 .. k1-1, printing rows when print; returns the last FairTen sum. */
static double run(MoorDyn md, unsigned int n, const double* x0, int k0, int k1, double dtc,
                  int every, int print, unsigned int nl, double* fair)
{
	double x[MAXDOF], xd[MAXDOF], f[MAXDOF], sum = 0.0;
	for (int k = k0; k < k1; k++) {
		double t = k * dtc, dt = dtc;
		double s0 = surge(k * dtc), s1 = surge((k + 1) * dtc);
		for (unsigned int i = 0; i < n; i++) {
			x[i] = x0[i] + (i % 3 == 0 ? s0 : 0.0);
			xd[i] = i % 3 == 0 ? (s1 - s0) / dtc : 0.0;
		}
		check(MoorDyn_Step(md, x, xd, f, &t, &dt), "MoorDyn_Step");
		if (print && (k + 1) % every == 0) {
			printf("%.17g", (k + 1) * dtc);
			for (unsigned int l = 0; l < nl; l++) {
				MoorDynLine line = MoorDyn_GetLine(md, l + 1);
				unsigned int nn;
				double fn[3];
				check(MoorDyn_GetLineNumberNodes(line, &nn), "GetLineNumberNodes");
				check(MoorDyn_GetLineNodeForce(line, nn - 1, fn), "GetLineNodeForce");
				fair[l] = sqrt(fn[0] * fn[0] + fn[1] * fn[1] + fn[2] * fn[2]);
				printf(",%.17g", fair[l]);
			}
			for (unsigned int i = 0; i < n; i++)
				printf(",%.17g", f[i]);
			printf("\n");
		}
		sum = f[0];
	}
	return sum;
}

int main(int argc, char** argv)
{
	if (argc < 5) {
		fprintf(stderr, "usage: moordyn_host DECK DURATION DTC EVERY [STATE_FILE]\n");
		return 2;
	}
	double duration = atof(argv[2]), dtc = atof(argv[3]);
	int every = atoi(argv[4]);
	MoorDyn md = MoorDyn_Create(argv[1]);
	if (!md) {
		fprintf(stderr, "moordyn_host: MoorDyn_Create failed\n");
		return 1;
	}
	unsigned int n, nl;
	check(MoorDyn_NCoupledDOF(md, &n), "MoorDyn_NCoupledDOF");
	check(MoorDyn_GetNumberLines(md, &nl), "MoorDyn_GetNumberLines");
	if (n > MAXDOF || nl > MAXLINES || n % 3 != 0) {
		fprintf(stderr, "moordyn_host: %u coupled dofs, %u lines: too many\n", n, nl);
		return 1;
	}
	/* The coupled points' deck positions: the end B node of the lines attached to them
	 * before Init is not available through the API, so they are given as the OC3 deck's. */
	const double oc3[9] = { 5.2, 0.0, -70.0, -2.6, 4.5, -70.0, -2.6, -4.5, -70.0 };
	double x0[MAXDOF], xd0[MAXDOF];
	for (unsigned int i = 0; i < n; i++) {
		x0[i] = oc3[i % 9];
		xd0[i] = 0.0;
	}
	check(MoorDyn_Init(md, x0, xd0), "MoorDyn_Init");
	int steps = (int)(duration / dtc + 0.5);
	double fair[MAXLINES];
	printf("t");
	for (unsigned int l = 0; l < nl; l++)
		printf(",FairTen%u", l + 1);
	for (unsigned int i = 0; i < n; i++)
		printf(",f%u", i);
	printf("\n");
	if (argc > 5) {
		int half = steps / 2;
		run(md, n, x0, 0, half, dtc, every, 1, nl, fair);
		check(MoorDyn_SaveState(md, argv[5]), "MoorDyn_SaveState");
		double a = run(md, n, x0, half, steps, dtc, every, 1, nl, fair);
		check(MoorDyn_LoadState(md, argv[5]), "MoorDyn_LoadState");
		double b = run(md, n, x0, half, steps, dtc, every, 0, nl, fair);
		if (a != b) {
			fprintf(stderr, "moordyn_host: after LoadState f0 = %.17g, first time %.17g\n",
			        b, a);
			return 1;
		}
	} else {
		run(md, n, x0, 0, steps, dtc, every, 1, nl, fair);
	}
	float fh[MAXLINES], fv[MAXLINES], ah[MAXLINES], av[MAXLINES];
	int nli = (int)nl;
	check(MoorDyn_GetFASTtens(md, &nli, fh, fv, ah, av), "MoorDyn_GetFASTtens");
	fprintf(stderr, "FairHTen1 %.1f FairVTen1 %.1f AnchHTen1 %.1f AnchVTen1 %.1f\n", fh[0],
	        fv[0], ah[0], av[0]);
	check(MoorDyn_Close(md), "MoorDyn_Close");
	return 0;
}
