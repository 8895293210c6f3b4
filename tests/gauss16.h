/* gauss16.h - the 16-point Gauss-Legendre rule (Abramowitz and Stegun,
 * Table 25.4), composed over equal parts, for the tests' own quadratures
 * (kept apart from the library's rules, so that a reference does not share
 * their code). */
#ifndef CANDELA_TESTS_GAUSS16_H
#define CANDELA_TESTS_GAUSS16_H

/* Node i (0..15) of the rule on [-1, 1] and its weight. */
static inline void gauss16_node(int i, double *x, double *w)
{
    static const double xs[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                                 0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
    static const double ws[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                                 0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
    *x = i < 8 ? -xs[7 - i] : xs[i - 8];
    *w = i < 8 ? ws[7 - i] : ws[i - 8];
}

/* The composite rule of `parts` equal parts on [0, 1]: 16 parts nodes and
 * weights into x[], w[] (summing to 1). */
static inline void gauss16_composite(int parts, double *x, double *w)
{
    for (int part = 0; part < parts; ++part)
        for (int i = 0; i < 16; ++i) {
            double t, wt;
            gauss16_node(i, &t, &wt);
            x[16 * part + i] = (part + 0.5 * (1.0 + t)) / parts;
            w[16 * part + i] = 0.5 * wt / parts;
        }
}

#endif
