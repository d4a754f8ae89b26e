"""Touches (double roots) next to crossings, in the plane and in space: each is found once.

Found by running the workbench's arbiter over mirrored curves: a curve and its mirror image in a
plane through one of its points containing its tangent there touch the curve at that point, at the
same parameter of both (``u = t = t0``), and may cross it elsewhere.
"""

from __future__ import annotations

from math import comb

import numpy as np
import pytest

from relief_cad import RationalBezier, intersect
from relief_cad.results import Intersection


def kinds(res: list) -> list[tuple[str, float]]:
    return [(r.kind, round(r.t, 5)) for r in res]


# rational quartics whose planar clipping puts a touch at t 0.78361 in a wide cluster; Newton from
# one of its diagonal seeds ran to the crossing at 0.69075 and its certificate dropped the touch
# (48 of 400 tolerances from 1e-9 to 1e-5 lost it)
W = [6.8449841763300014, 8.310810722367389, 7.339304908232734, 7.7867310286109905, 8.570643851345087]
A1 = RationalBezier([[-0.3685178935923222, -0.01721421694384867], [0.01222375767441465, 0.21323717674109396],
                     [0.13124275808147945, 0.10403720672910652], [0.008597417749710982, 0.12972040203178853],
                     [0.015985853498951742, -0.163218751713534]], W)
B1 = RationalBezier([[0.40564939672365063, -0.15296097460207506], [0.1145687965468782, 0.1952914337949257],
                     [-0.027419316987711034, 0.1318578890588626], [0.09316554874023049, 0.1148917600486149],
                     [-0.018672918900192823, -0.15714149162201285]], W)


@pytest.mark.parametrize("tol", [None, 2.698e-09, 1.2965e-08, 7.435870023658868e-08, 7.5e-8, 1e-7, 4.668e-06])
def test_a_newton_root_outside_its_cluster_does_not_drop_the_cluster_touch(tol: float | None) -> None:
    assert kinds(intersect(A1, B1, tol=tol)) == [("crossing", 0.69075), ("tangent", 0.78361)]


def test_a_touch_and_a_crossing_in_one_wide_cluster_are_two_contacts() -> None:
    # at this tolerance the quartics (within 1e-7 of each other between) form one cluster from the
    # touch at 0.41084 to the crossing at 0.41442, 0.0036 apart: the certified crossing no longer
    # explains away the touch, which no Newton step can certify (a double root)
    a = RationalBezier([[4.521082715446405, 2.2819218323537833], [1.0363932926552466, 1.3361979795344132],
                        [2.6160696127985936, 0.7463953788680545], [0.33921238050572916, 0.12501921362702484],
                        [0.8111868720620812, 0.3928146417380366]],
                       [0.6279077595253004, 1.7816241800821162, 0.8574229346019018, 1.38147120339321,
                        2.859422839145912])
    b = RationalBezier([[1.1422930199879975, 1.64140667874429], [3.2908995204481863, 1.502934170688972],
                        [0.730053093124068, 0.9363059777404436], [1.07067169156457, -0.3003437626284062],
                        [1.1455368784134856, 0.27928207656141213]],
                       [1.452719948828002, 0.9307744607177524, 1.6061063132355853, 0.9773660769650995,
                        2.488203648024943])
    assert kinds(intersect(a, b, tol=2.4663397493769742e-06)) == [("tangent", 0.41084), ("crossing", 0.41442)]


MIRROR_A = np.array([[0.22132417463217868, 0.94089899147737466], [0.82240931814185425, 0.48459761761653741],
                     [0.64108822854342173, 0.24671568029724278], [0.17360103145910455, 0.54284616173057065],
                     [0.37484967714882089, 0.32195014919176868]])
MIRROR_B = np.array([[0.23714527487369813, -0.12526962798777785], [0.82442643356508549, 0.34866616321334698],
                     [0.63612677511714422, 0.58106322056204118], [0.17763216614067445, 0.27119190047707481],
                     [0.37223779914345645, 0.49796207786174346]])


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("tol", [1e-10, 1e-9, 1e-7, 1e-5])
def test_a_touch_7e_4_after_a_crossing_is_a_contact_of_its_own(dim: int, tol: float) -> None:
    # a quartic and its mirror image in a plane tangent to it at 0.69139 (workbench corpus, tangent
    # family, seed 6060) cross at 0.69071: within 1e-3, and within tol between from 1e-9 on. The
    # touch was merged into the crossing, though the curves part by far more than rounding between
    # them: two contacts, as the exact arbiter says
    a = RationalBezier(np.c_[MIRROR_A, np.zeros((5, dim - 2))])
    b = RationalBezier(np.c_[MIRROR_B, np.zeros((5, dim - 2))])
    assert kinds(intersect(a, b, tol=tol)) == [("crossing", 0.69071), ("tangent", 0.69139)]
    assert kinds(intersect(b, a, tol=tol)) == [("crossing", 0.69071), ("tangent", 0.69139)]


def test_space_touch_next_to_a_crossing_in_an_ill_conditioned_model_frame() -> None:
    # control points at depths 0.025 to 0.97 and up to 37 times off the z axis: the model's own frame
    # magnified the tolerance 1,600 times in the plane, and the touch at 0.34865 merged into the
    # crossing at 0.31297; such a frame is no longer taken
    a = RationalBezier([[0.9256572434263927, 0.4434082666178205, 0.02515323800512148],
                        [0.566249917231599, 0.8753265460467363, 0.9458520699684614],
                        [0.2656588275661088, 0.8174945768407229, 0.7609589816475101],
                        [0.8635481317154379, 0.830830122944415, 0.656607848206929],
                        [0.45685318544922005, 0.4083925014979395, 0.6801516062011208]])
    b = RationalBezier([[0.9616473265132441, 0.35856001570969004, 0.09638041792974619],
                        [0.5173769332129989, 0.990546819382371, 0.8491286248531622],
                        [0.3180133589929316, 0.6940663978070502, 0.864572680476955],
                        [0.847179217094481, 0.8694205805296638, 0.6242124901838831],
                        [0.31908478398241946, 0.7331877476400006, 0.4074972003881832]])
    for res in (intersect(a, b, tol=1e-7), intersect(b, a, tol=1e-7)):
        assert kinds(res) == [("crossing", 0.31297), ("tangent", 0.34865)]


def test_space_touch_found_from_several_planar_rows_is_one_tangent() -> None:
    # four spurious planar crossings of the projections polish in space onto the touch, 3e-6 apart
    # in parameter (three tangents; two the other way round)
    a = RationalBezier([[0.36278430649632154, 0.9983540036182748, 0.837887610992178],
                        [0.5404815038294141, 0.3201530210646988, 0.9001224642704789],
                        [0.2828672457949699, 0.4628350217719932, 0.5934796826215165],
                        [0.7673220979417956, 0.7070200160512528, 0.6867470543393079],
                        [0.207285492022398, 0.33854048091099953, 0.7498937130399818]])
    b = RationalBezier([[0.7704609629541801, 0.7871992636904623, 1.0257223070059653],
                        [0.19486790685004085, 0.49916241007355666, 0.7408829691988186],
                        [0.5759332662952603, 0.3110424715728024, 0.7285081813119553],
                        [0.5187631934222265, 0.8357602566541553, 0.5722249556800256],
                        [0.41813491675245484, 0.22933173732082973, 0.8470413838018128]])
    for res in (intersect(a, b, tol=1e-7), intersect(b, a, tol=1e-7)):
        assert kinds(res) == [("tangent", 0.54649)]


def mirrored(rng: np.random.Generator, dim: int) -> tuple[RationalBezier, RationalBezier, float, float]:
    """A random curve, its mirror image in a plane through ``a(t0)`` containing ``a'(t0)``, t0, bend.

    ``bend``: the curvature of ``a`` at ``t0`` towards the plane's normal. Below about 0.05 the touch
    is flat, and the mirror may genuinely cross the curve again close by (where ``a`` meets the plane).
    """
    deg = int(rng.integers(2, 5))
    p = rng.uniform(0, 1, (deg + 1, dim))
    t0 = float(rng.uniform(0.2, 0.8))
    basis = np.array([comb(deg, i) * t0**i * (1 - t0) ** (deg - i) for i in range(deg + 1)])
    dbasis = np.array([comb(deg - 1, i) * t0**i * (1 - t0) ** (deg - 1 - i) for i in range(deg)])
    d = dbasis @ (deg * (p[1:] - p[:-1]))
    d /= np.linalg.norm(d)
    m = rng.normal(size=dim)
    m -= (m @ d) * d
    m /= np.linalg.norm(m)
    q = p - 2.0 * np.outer((p - basis @ p) @ m, m)
    d2basis = np.array([comb(deg - 2, i) * t0**i * (1 - t0) ** (deg - 2 - i) for i in range(deg - 1)])
    d2 = d2basis @ (deg * (deg - 1) * (p[2:] - 2.0 * p[1:-1] + p[:-2]))
    bend = abs(d2 @ m) / float(np.linalg.norm(dbasis @ (deg * (p[1:] - p[:-1])))) ** 2
    return RationalBezier(p), RationalBezier(q), t0, bend


@pytest.mark.parametrize("dim", [2, 3])
def test_mirror_touches_are_found_once(dim: int) -> None:
    """Every mirror touch is found once, at u = t = t0; every result is within tol (1,000 pairs).

    Pairs whose touch is flat (``bend`` below 0.05) are left out: there the rules for contacts within
    1e-3 of each other decide, not the touch alone.

    Once: one tangent, or in the plane two crossings closer than ``CLUSTER_GAP`` (rounding puts
    the mirror a little across the curve, and the exact data then cross twice, which the core
    reports as such; see :mod:`relief_cad.contacts`).
    """
    rng = np.random.default_rng(20261205 + dim)
    for _ in range(1000):
        a, b, t0, bend = mirrored(rng, dim)
        if bend < 0.05:
            continue
        res = intersect(a, b, tol=1e-7)
        near = [r for r in res if isinstance(r, Intersection) and abs(r.t - t0) <= 1e-5]
        found = [r.kind for r in near]
        if dim == 2 and found == ["crossing", "crossing"]:
            assert abs(near[1].t - near[0].t) <= 1e-6 and abs(near[1].u - near[0].u) <= 1e-6, (t0, res)
        else:
            assert found == ["tangent"], (t0, res)
        assert all(abs(r.t - t0) <= 1e-6 and abs(r.u - t0) <= 1e-6 for r in near), (t0, res)
        assert all(r.distance <= res.tol_used for r in res if isinstance(r, Intersection))


@pytest.mark.parametrize(("a", "b", "t0"), [
    ([[0.2284782793920619, 0.061968380129556744], [0.4205670608217096, 0.8601938452188314],
      [0.7315440627700559, 0.9866372056721671], [0.1081489505214085, 0.35517863872143285],
      [0.5013675717219137, 0.4180924104096625]],
     [[0.39828390375096995, 1.4045409427950655], [0.3855874106069422, 0.5836263357073616],
      [0.6552909227657897, 0.38373978120032026], [0.20874228990597854, 1.1505224793893263],
      [0.5739148146621491, 0.9916890638557267]], 0.4342189355276773),
    ([[0.7851223775683476, 0.46941022590692005], [0.7098149955705444, 0.3556254513742886],
      [0.13944354043724183, 0.5044500756594107], [0.26670577838882403, 0.32593181115277214],
      [0.9921260788540938, 0.5522644828846969]],
     [[0.008435272591425902, 0.0021104456583598274], [0.7825464695380031, 0.8469115234313337]],
     0.5725896675016249),
])
def test_a_touch_found_exactly_is_not_moved_by_its_post_pass(a: list, b: list, t0: float) -> None:
    # a quartic touching its mirror image, and a quartic touching a line, at t0 (workbench corpus,
    # tangent family, seed 8080): the kernel found the touch 1e-16 apart; the post-pass fitting the
    # tangency function on a window of 1e-2 moved it 8e-5 along, to where the curves are 3.8e-8
    # apart (within tol 1e-7, so it was taken), 9e-7 from the true touch in space
    found = intersect(RationalBezier(a), RationalBezier(b), tol=1e-7)
    assert [r.kind for r in found] == ["tangent"]
    assert abs(found[0].t - t0) <= 1e-8 and found[0].distance <= 1e-12


# pieces of an arc (rational quadratics) and of a cubic spline through 9 of its points (radius 1
# and 10, build123d): the spline crosses the arc at sin 3.6e-4, 1e-5 and 9.5e-5 at its span ends and
# between, and touches it at the end of its middle span
ARC_0 = RationalBezier([[0.6044424804277685, -0.7966487857609065], [1.1622619655231674, -0.3734136045512079],
                        [0.9553364891256059, 0.29552020666134005]], [1.0, 0.8191520442889917, 1.0])
ARC_1 = RationalBezier([[9.55336489125606, 2.9552020666134005], [7.484110127280449, 9.64454017873887],
                        [0.4904616544219357, 9.987965126367918]], [1.0, 0.8191520442889919, 1.0])
SPAN_0 = RationalBezier([[0.9800665778412416, -0.19866933079506122], [0.9917335049586993, -0.1414980034765912],
                         [0.9982502233912, -0.08331191376174467], [0.9996875162757026, -0.024997395914712367]])
SPAN_2 = RationalBezier([[0.9887710779360421, 0.14943813247359916], [0.9800594793753743, 0.20711619703566023],
                         [0.9662784149175339, 0.2640293801805644], [0.9476507264148157, 0.31930878585700084]])
SPAN_3 = RationalBezier([[9.476507264148157, 3.193087858570008], [9.290230379120977, 3.7458819153343734],
                         [9.055487253645019, 4.282338197414063], [8.775825618903728, 4.794255386042028]])


@pytest.mark.parametrize(("a", "b", "want"), [
    (ARC_0, SPAN_0, [("crossing", 0.588), ("crossing", 0.72822)]),
    (ARC_0, SPAN_2, [("crossing", 0.87203), ("crossing", 0.95116), ("crossing", 0.98861)]),
    (ARC_1, SPAN_3, [("crossing", 0.02171), ("tangent", 0.16956)]),
], ids=["crossing-at-a-span-end", "crossing-at-sin-1e-5", "touch-at-a-span-end"])
def test_a_spline_fitted_to_an_arc_gives_its_crossings_and_its_touch(a: RationalBezier, b: RationalBezier,
                                                                    want: list[tuple[str, float]]) -> None:
    # a crossing at a span end was found twice, 2e-11 apart, and taken for a split double root; the
    # flanks of a crossing at sin 1e-5 (or of the touch), where the closest-approach iteration stalls
    # 1e-8 (1e-10) off, came out as 6 touches (1), chained into an overlap by the post-pass
    for tol in (1e-9, 1e-7):
        assert kinds(intersect(a, b, tol=tol)) == want, tol
        assert sorted((r.kind, round(r.u, 5)) for r in intersect(b, a, tol=tol)) == sorted(want), tol


def test_an_end_within_tol_on_the_flank_of_a_small_angle_crossing_is_that_crossing() -> None:
    # a piece of a nearly straight spline crosses a line 9e-3 of its range before its end, where it
    # is 4.5e-8 off the line (within tol 1e-7): the end was a second contact; the distance falls all
    # the way from it to the crossing, so the crossing is the one contact
    a = RationalBezier([[-32.01319389570317, -181.92500603806553], [-32.00782693744508, -181.92890318931214],
                        [-32.00246131652942, -181.93280218330472], [-31.997093214861238, -181.93669775858712]])
    b = RationalBezier([[-32.037360785894556, -181.90749033543418], [-31.94071855257864, -181.9775880643706]])
    for tol in (1e-7, 1e-6):
        assert kinds(intersect(a, b, tol=tol)) == [("crossing", 0.99066)], tol
        assert [(r.kind, round(r.u, 5)) for r in intersect(b, a, tol=tol)] == [("crossing", 0.99066)], tol
    # an end meeting as close as rounding stays: the end of a cut at its crossing
    cut = a.segment(0.0, 0.9906624655754577)
    assert [r.t for r in intersect(cut, b, tol=1e-7)] == [1.0]
