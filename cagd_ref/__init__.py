"""cagd_ref: the mathematics of the CAGD course, after T. W. Sederberg's course notes (BYU).

One flat module per topic, in NumPy; import them by name (``from cagd_ref import
bezier``). Control points are float arrays (n+1, d), rational curves live in
homogeneous coordinates, B-spline knots follow the notes' convention. The
drawings, explorers and grader of the course are in `cagd_course`; nothing here
imports them. The modules, in the order of the course (module, chapters, topic):

Part I. Curves

    geometry              1        points, vectors, lines, planes, rotations, conics
    bezier                2        Bézier curves: de Casteljau, subdivision, elevation, hodographs, rational curves
    continuity            2        parametric and geometric continuity of joined curves, curvature combs
    polynomials           2, 3, 9  scalar polynomials in the power and Bernstein bases, conversions, products
    forward_differencing  4        forward differencing: many evaluations for n additions each
    blending              5        Timmer, Ball and Overhauser curves and their Bézier forms
    blending_properties   5        which of the six properties a set of blending functions has
    bspline               6        B-splines in polar form: de Boor, knot insertion, Bézier segments, basis
    knot_intervals        6        B-splines labelled with knot intervals, splitting and closing them

Part II. Intersections, offsets and roots

    intersection          7        intersections of lines and curves: Bézout, substitution, subdivision, Bézier clipping
    offsets               8        offset curves, their cusps, Pythagorean-hodograph curves and their exact offsets
    roots                 9        real roots of polynomials in Bernstein form: hull marching, deflation, clipping

Part III. Interpolation and approximation

    interpolation         10       Lagrange, Newton and Neville interpolation, Chebyshev nodes, Hermite curves
"""
