/* A coupling host on hawser's C ABI (hawser.h): the OC3 deck's three fairleads in a surge
 * x = x0 + A sin(2 pi t / T), with the kinematics at the end of every coupling interval of
 * DTC seconds (hawser's convention).
 *
 *   hawser_host DECK DURATION DTC
 *
 * Prints a CSV row per interval: t, then the coupled forces. Then checks the API's contract:
 * a checkpoint saved half-way and loaded back repeats the second half to the last bit, the
 * line queries answer, and errors come back as status codes with a message. */
#include "hawser.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define A 2.0
#define T 10.0

static void check(HawserStatus s, const char* what)
{
	if (s != HAWSER_STATUS_OK) {
		fprintf(stderr, "hawser_host: %s failed (%d): %s\n", what, (int)s,
		        hawser_last_error());
		exit(1);
	}
}

static void kinematics(const double* x0, size_t n, double t, double* x, double* xd)
{
	double w = 2.0 * M_PI / T;
	for (size_t i = 0; i < n; i++) {
		x[i] = x0[i] + (i % 3 == 0 ? A * sin(w * t) : 0.0);
		xd[i] = i % 3 == 0 ? A * w * cos(w * t) : 0.0;
	}
}

static void run(HawserSession* s, const double* x0, size_t n, int k0, int k1, double dtc,
                int print, double* last)
{
	double x[64], xd[64], f[64];
	for (int k = k0; k < k1; k++) {
		kinematics(x0, n, (k + 1) * dtc, x, xd);
		check(hawser_step(s, k * dtc, dtc, x, xd, NULL, f), "hawser_step");
		if (print) {
			printf("%.17g", (k + 1) * dtc);
			for (size_t i = 0; i < n; i++)
				printf(",%.17g", f[i]);
			printf("\n");
		}
	}
	memcpy(last, f, n * sizeof(double));
}

int main(int argc, char** argv)
{
	if (argc < 4) {
		fprintf(stderr, "usage: hawser_host DECK DURATION DTC\n");
		return 2;
	}
	double duration = atof(argv[2]), dtc = atof(argv[3]);
	HawserSession* s = NULL;

	/* Errors are status codes with a message, never a crash. */
	if (hawser_create("no/such/deck.txt", &s) != HAWSER_STATUS_INPUT_ERROR || s != NULL ||
	    strlen(hawser_last_error()) == 0) {
		fprintf(stderr, "hawser_host: a missing file was not an input error\n");
		return 1;
	}
	if (hawser_coupled_dofs(NULL, NULL) != HAWSER_STATUS_INVALID_ARGUMENT) {
		fprintf(stderr, "hawser_host: a null session was accepted\n");
		return 1;
	}

	check(hawser_create(argv[1], &s), "hawser_create");
	size_t n, lines, nodes;
	check(hawser_coupled_dofs(s, &n), "hawser_coupled_dofs");
	if (n != 9) {
		fprintf(stderr, "hawser_host: %zu coupled dofs, expected 9\n", n);
		return 1;
	}
	double f[64], x[64], xd[64];
	if (hawser_step(s, 0.0, dtc, x, xd, NULL, f) != HAWSER_STATUS_STATE_ERROR) {
		fprintf(stderr, "hawser_host: a step before init was accepted\n");
		return 1;
	}
	const double x0[9] = { 5.2, 0.0, -70.0, -2.6, 4.5, -70.0, -2.6, -4.5, -70.0 };
	kinematics(x0, n, 0.0, x, xd);
	/* The statics at the deck positions, then the initial velocities. */
	check(hawser_init(s, x0, xd), "hawser_init");
	int steps = (int)(duration / dtc + 0.5), half = steps / 2;
	printf("t");
	for (size_t i = 0; i < n; i++)
		printf(",f%zu", i);
	printf("\n");
	double a[64], b[64];
	run(s, x0, n, 0, half, dtc, 1, a);

	size_t len = 0;
	check(hawser_checkpoint_save(s, NULL, 0, &len), "hawser_checkpoint_save (size)");
	unsigned char* buf = malloc(len);
	if (hawser_checkpoint_save(s, buf, len - 1, &len) != HAWSER_STATUS_BUFFER_TOO_SMALL) {
		fprintf(stderr, "hawser_host: a short buffer was accepted\n");
		return 1;
	}
	check(hawser_checkpoint_save(s, buf, len, &len), "hawser_checkpoint_save");
	run(s, x0, n, half, steps, dtc, 1, a);
	check(hawser_checkpoint_load(s, buf, len), "hawser_checkpoint_load");
	run(s, x0, n, half, steps, dtc, 0, b);
	if (memcmp(a, b, n * sizeof(double)) != 0) {
		fprintf(stderr, "hawser_host: the run from the checkpoint differs\n");
		return 1;
	}
	unsigned char bad[16] = { 0 };
	if (hawser_checkpoint_load(s, bad, sizeof bad) != HAWSER_STATUS_CHECKPOINT_ERROR) {
		fprintf(stderr, "hawser_host: a damaged checkpoint was accepted\n");
		return 1;
	}
	free(buf);

	/* Line queries: the fairlead tension is the largest along a catenary line. */
	check(hawser_line_count(s, &lines), "hawser_line_count");
	check(hawser_line_node_count(s, 0, &nodes), "hawser_line_node_count");
	double* tension = malloc(nodes * sizeof(double));
	double* pos = malloc(3 * nodes * sizeof(double));
	check(hawser_line_tensions(s, 0, tension, nodes), "hawser_line_tensions");
	check(hawser_line_node_positions(s, 0, pos, 3 * nodes), "hawser_line_node_positions");
	if (hawser_line_tensions(s, lines, tension, nodes) != HAWSER_STATUS_INVALID_ARGUMENT) {
		fprintf(stderr, "hawser_host: a line index out of range was accepted\n");
		return 1;
	}
	double reaction[3], net[3], point[3], pf[3];
	check(hawser_line_end_force(s, 0, 1, reaction, net), "hawser_line_end_force");
	check(hawser_point(s, 3, point, pf), "hawser_point");
	fprintf(stderr,
	        "lines %zu, nodes %zu, tension A %.1f N B %.1f N, fairlead z %.3f m, "
	        "end force %.1f N, point P4 force x %.1f N\n",
	        lines, nodes, tension[0], tension[nodes - 1], pos[3 * nodes - 1],
	        sqrt(reaction[0] * reaction[0] + reaction[1] * reaction[1] +
	             reaction[2] * reaction[2]),
	        pf[0]);
	if (!(tension[nodes - 1] > tension[0]) || fabs(pos[3 * nodes - 1] + 70.0) > 1e-9 ||
	    fabs(pf[0] - b[0]) > 1e-9 * fabs(b[0])) {
		fprintf(stderr, "hawser_host: line or point queries disagree\n");
		return 1;
	}
	free(tension);
	free(pos);
	check(hawser_close(s), "hawser_close");
	return 0;
}
