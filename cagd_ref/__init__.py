"""cagd_ref: the mathematics of the CAGD course, after T. W. Sederberg's course notes (BYU).

One flat module per topic, in NumPy; import them by name (``from cagd_ref import
bezier``). Control points are float arrays (n+1, d), rational curves live in
homogeneous coordinates, B-spline knots follow the notes' convention. The
drawings, explorers and grader of the course are in `cagd_course`; nothing here
imports them. The modules, in the order of the course (module, chapters, topic):

Part I. Curves

    geometry              1        points, vectors, lines, planes, rotations, conics
    bezier                2        de Casteljau, subdivision, elevation, hodographs, rational curves, boxes, arc length
    continuity            2        parametric and geometric continuity of joined curves, curvature combs
    polynomials           2, 3, 9  power and Bernstein bases: Horner (with p'), conversions (on [t0, t1], rational)
    forward_differencing  4        n additions per value: the difference table, raster steps, adaptive steps, drift
    blending              5        Timmer, Ball, Overhauser and Catmull-Rom curves, Bézier forms, crossing counts
    blending_properties   5        which of the six properties a set of blending functions has
    bspline               6        B-splines in polar form: de Boor, knot insertion, Bézier segments, basis
    knot_intervals        6        B-splines labelled with knot intervals, splitting and closing them

Part II. Intersections, offsets and roots

    intersection          7        intersections of lines and curves: Bézout, substitution, subdivision, Bézier clipping
    offsets               8        offset curves and their cusps, PH curves and the parabola with exact rational offsets
    roots                 9        real roots in Bernstein form: hull marching, deflation, derivatives, line ∩ curve

Part III. Interpolation and approximation

    interpolation         10       Lagrange, Newton, Neville; error bounds, Chebyshev nodes, flattening, Hermite curves
    approximation         11       best constants, least-squares B-spline fits, parameters, fairing, constraints, boxes
    interval_bezier       12       interval arithmetic and interval Bézier curves: containment, subdivision, enclosures
    floating              13       floating-point numbers, rounding error and guaranteed bounds for de Casteljau

Part IV. Deformations and surfaces

    ffd                   14       free-form deformation: a tensor-product lattice bends whatever lies in its box
    surfaces              15, 16   Bézier and NURBS patches: points, normals, curvature, tessellation, the O(n²) method
    tsplines              15       T-meshes, knot inference and T-spline surfaces, local refinement

Part V. Algebraic geometry

    algebra               17       resultants, GCDs, implicitization, inversion and intersection of rational curves
    moving_lines          18       moving lines and pencils: conics, double points, compact implicit equations
    plane_curves          19       genus, double points, discriminants, implicit curves' intersections, parametrization

Part VI. Hybrid curves, integrals and maps of quadrilaterals

    hybrid                20       hybrid curves (a polynomial curve with a moving point), integrals with error bounds
    quad_maps             21       bilinear, birational and projective maps of quadrilaterals and their inverses
"""
