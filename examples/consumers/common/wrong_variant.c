/*
 * A CalculiX-style host: gapcon called with CalculiX's argument list (AREA after KINC), declared
 * here by hand as CalculiX's gapcon.f is (no interfacial.h, whose gapcon_ has Abaqus's list).
 * Linked against the Abaqus build (WANT_REFUSAL) it must get AK(1) = 0 and a message naming the
 * library to link; linked against libinterfacial_calculix, the configured k = 2.
 */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

void gapcon_(double *ak, const double *d, const double *flowm, const double *temp,
             const double *predef, const double *time, const char *ciname, const char *slname,
             const char *msname, const double *coords, const int *noel, const int *node,
             const int *npred, const int *kstep, const int *kinc, const double *area,
             size_t ciname_len, size_t slname_len, size_t msname_len);
const char *ifl_last_error(void);
const char *ifl_version(void);

int main(void)
{
    double ak[5] = {-1, -1, -1, -1, -1}, d[2] = {0, 1}, temp[2] = {300, 290}, zeros[4] = {0};
    double area = 2.5;
    int one = 1, zero = 0, fails = 0;
    char name[80];
    memset(name, ' ', sizeof name);
    memcpy(name, "SI1", 3);
    gapcon_(ak, d, zeros, temp, zeros, zeros, name, name, name, zeros, &one, &one, &zero, &one,
            &one, &area, 80, 80, 80);
#ifdef WANT_REFUSAL
    fails += ak[0] != 0.0;
    fails += strstr(ifl_last_error(), "libinterfacial_calculix") == NULL;
    fails += strstr(ifl_last_error(), "'SI1'") == NULL;
    fails += strstr(ifl_version(), "calculix") != NULL;
    printf("refused (%s): %s\n", ifl_version(), ifl_last_error());
#else
    fails += ak[0] != 2.0;
    fails += strcmp(strchr(ifl_version(), '+') ? strchr(ifl_version(), '+') : "", "+calculix");
    printf("CalculiX variant (%s): AK(1) = %g\n", ifl_version(), ak[0]);
#endif
    fails += ak[1] != -1.0 || ak[4] != -1.0;
    printf("%d passed, %d failed\n", fails ? 0 : 1, fails ? 1 : 0);
    return fails != 0;
}
