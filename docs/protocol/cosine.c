/* docs/protocol/cosine.c - a cosine-weighted hemisphere sampler that speaks
 * mcbox-check's --exec protocol (docs/check-protocol.md) with stdio only.
 *
 *   cc -O2 -o cosine docs/protocol/cosine.c -lm
 *   mcbox-check --exec ./cosine --domain hemisphere --invert
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

int main(void)
{
    char line[512], cmd[16];
    long k;
    while (fgets(line, sizeof line, stdin)) {
        if (strncmp(line, "hello ", 6) == 0) {
            puts("ok");
        } else if (sscanf(line, "%15s %ld", cmd, &k) == 2) {
            for (long i = 0; i < k && fgets(line, sizeof line, stdin); i++) {
                char *p = line;
                double v[3] = {0, 0, 0};
                for (int j = 0; j < 3; j++)
                    v[j] = strtod(p, &p);
                if (strcmp(cmd, "sample") == 0) { /* Malley: the disc lifted */
                    double r = sqrt(v[0]), phi = 2.0 * PI * v[1], z = sqrt(fmax(0.0, 1.0 - v[0]));
                    printf("%.17g %.17g %.17g %.17g\n", r * cos(phi), r * sin(phi), z, z / PI);
                } else if (strcmp(cmd, "pdf") == 0) { /* per unit solid angle */
                    printf("%.17g\n", v[2] >= 0.0 ? v[2] / PI : 0.0);
                } else if (strcmp(cmd, "invert") == 0) {
                    double u2 = atan2(v[1], v[0]) / (2.0 * PI);
                    printf("%.17g %.17g\n", v[0] * v[0] + v[1] * v[1], u2 < 0.0 ? u2 + 1.0 : u2);
                } else {
                    printf("error unknown command %s\n", cmd);
                    return 2;
                }
            }
        } else {
            line[strcspn(line, "\r\n")] = '\0';
            printf("error cannot read '%s'\n", line);
            return 2;
        }
        fflush(stdout); /* the whole batch's answers, now: mcbox-check waits for them */
    }
    return 0;
}
