/* gauss_legendre.h - the 8-point Gauss-Legendre rule on [0, 1], for tests
 * that integrate smooth functions independently of the library
 * (Abramowitz and Stegun, Table 25.4, mapped from [-1, 1]). */
#ifndef CANDELA_TESTS_GAUSS_LEGENDRE_H
#define CANDELA_TESTS_GAUSS_LEGENDRE_H

static const double gl8_x[8] = {0.019855071751231856, 0.101666761293186631, 0.237233795041835507,
                                0.408282678752175098, 0.591717321247824902, 0.762766204958164493,
                                0.898333238706813369, 0.980144928248768144};
static const double gl8_w[8] = {0.050614268145188130, 0.111190517226687235, 0.156853322938943644,
                                0.181341891689180991, 0.181341891689180991, 0.156853322938943644,
                                0.111190517226687235, 0.050614268145188130};

#endif
