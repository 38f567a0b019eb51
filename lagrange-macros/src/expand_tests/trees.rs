//! Bodies placed from other bodies: the tree of translations and the rigid tree pass.

use super::{pretty, snapshot};
use crate::expand::expand;
use proc_macro2::TokenStream;
use quote::quote;

#[test]
fn a_body_translated_from_another_is_seeded_on_its_own_angle() {
    // Drag on the second bob: a force, so the equations are not derived in closed form and the
    // tree of translations serves.
    let out = pretty(expand(
        TokenStream::new(),
        quote! {
            pub mod double_pendulum {
                pub struct Coords { pub theta1: f64, pub theta2: f64 }
                pub struct DoublePendulum { pub m1: f64, pub m2: f64, pub l1: f64, pub l2: f64, pub g: f64, pub c: f64 }
                #[particle(mass = m1)]
                fn bob1() -> Vec2 { vec2(theta1.sin(), -theta1.cos()) * l1 }
                #[particle(mass = m2)]
                fn bob2() -> Vec2 { bob1 + vec2(theta2.sin(), -theta2.cos()) * l2 }
                #[gravity]
                fn down() -> Vec2 { vec2(0.0, -g) }
                #[force(on = bob2)]
                fn drag() -> Vec2 { -bob2_dot * c }
            }
        },
    ));
    // Compared without whitespace: the pretty-printer breaks lines where it likes.
    let out: String = out.split_whitespace().collect();
    assert!(!out.contains("__lagrange_closed_form"));
    // Two coordinates, four rows, seeds one wide, two bodies: bob2 is bob1 plus its own arm.
    assert!(out.contains("Tree<2,4,1,2>forDoublePendulum"));
    assert!(out.contains("tree::equations_of_motion::<Self,S,2,4,1,2,>"));
    assert!(out.contains("parent:::lagrange::__private::core::option::Option::Some(0)"));
    // The arm alone, seeded on theta2 only: bob1 is not evaluated again on the seeds.
    assert!(out.contains("fn__lagrange_displacement_bob2<__D:::lagrange::__private::Scalar>(&self,__t:__D,theta2:__D,)"));
    assert!(out.contains("tree::seed(__q[1],__v[1],0)"));
}

/// A spatial arm as the README writes it: the tree pass, its three sweeps written body by body, the
/// joint with no constant rotation before it known as such.
#[test]
fn a_spatial_arm_takes_the_rigid_tree_pass() {
    let out = snapshot(
        "spatial_arm",
        quote! {
            pub mod arm {
                pub struct Coords { pub q1: f64, pub q2: f64 }
                pub struct Arm { pub m1: f64, pub m2: f64, pub d: f64, pub e: f64, pub g: f64 }
                #[rigid_body(mass = m1, inertia = [0.03, 0.025, 0.01])]
                fn link1() -> Spatial {
                    let r = rot_z(q1);
                    spatial(r * vec3(0.0, 0.0, 0.5 * d), r)
                }
                #[rigid_body(mass = m2, inertia = [0.03, 0.025, 0.01])]
                fn link2() -> Spatial {
                    let r = link1.rotation * rot_y(q2);
                    let joint = link1.point(vec3(-e, 0.0, 0.5 * d));
                    spatial(joint + r * vec3(e, 0.0, 0.5 * d), r)
                }
                #[gravity]
                fn down() -> Vec3 { vec3(0.0, 0.0, -g) }
            }
        },
    );
    let squeezed: String = out.split_whitespace().collect();
    assert!(out.contains("tree::rigid::RigidTree<2, 2> for Arm"));
    assert!(squeezed
        .contains("JointKind::Revolute(::lagrange::__private::tree::rigid::spatial::Axis::Y,)"));
    // The second joint's offset from the first's: (−e, 0, d/2) + (0, 0, d/2), y structurally zero.
    assert!(out.contains("offset: [true, false, true]"));
    // The second joint follows its parent's frame with no constant rotation between.
    assert!(out.contains("rotated: false"));
    // Each body's step is compiled for its own joint (its code a constant of the tree).
    for b in 0..2 {
        let code = format!("{{<Armas::lagrange::__private::tree::rigid::RigidTree<2,2,>>::JOINTS[{b}].code()}},2,>");
        assert!(squeezed.contains(&format!("__ws.velocity::<{code}(__joints,__k,__q,__v,{b})")));
        assert!(squeezed.contains(&format!(".articulate::<{code}(__joints,__k,__tau,{b})")));
        assert!(squeezed.contains(&format!("__ws.accelerate::<{code}(__joints,__k,__qdd,{b})")));
    }
    assert!(out.contains("type Prepared = ::lagrange::__private::tree::rigid::RigidConstants<2>"));
    assert!(out.contains("fn inverse_dynamics_at"));
    // No dense pass for q̈.
    assert!(!out.contains("dynamics::equations_of_motion::<Self"));
}

/// A branched tree (a torso and two legs) is one tree with two branches: both legs' parent is the
/// torso.
#[test]
fn a_branched_tree_takes_the_rigid_tree_pass() {
    let out = snapshot(
        "branched_tree",
        quote! {
            pub mod legs {
                pub struct Coords { pub yaw: f64, pub left: f64, pub right: f64 }
                pub struct Legs { pub m: f64, pub w: f64, pub g: f64 }
                #[rigid_body(mass = m, inertia = [0.2, 0.15, 0.1])]
                fn torso() -> Spatial { spatial(vec3(0.0, 0.0, 1.0), rot_z(yaw)) }
                #[rigid_body(mass = m, inertia = [0.05, 0.05, 0.01])]
                fn left_leg() -> Spatial {
                    let r = torso.rotation * rot_x(left);
                    spatial(torso.point(vec3(w, 0.0, -0.3)) + r * vec3(0.0, 0.0, -0.2), r)
                }
                #[rigid_body(mass = m, inertia = [0.05, 0.05, 0.01])]
                fn right_leg() -> Spatial {
                    let r = torso.rotation * rot_x(right);
                    spatial(torso.point(vec3(-w, 0.0, -0.3)) + r * vec3(0.0, 0.0, -0.2), r)
                }
                #[gravity]
                fn down() -> Vec3 { vec3(0.0, 0.0, -g) }
            }
        },
    );
    assert!(out.contains("tree::rigid::RigidTree<3, 3> for Legs"));
    assert_eq!(
        out.matches("parent: ::lagrange::__private::core::option::Option::Some(0)")
            .count(),
        2
    );
}

/// A body declared by its joint frame, with its centre of mass and a full tensor in that frame:
/// x holds the centre of mass and the principal axes (`principal` of the frame), the bodies seen
/// by potentials and forces are the frames mapped back (`frame`), the tensor's principal moments
/// are computed once per `masses`, and `validate` checks the tensor, the centre of mass and the
/// constant rotations (`rot3`, `rot_axis`).
#[test]
fn a_body_declared_by_its_frame() {
    let out = snapshot(
        "framed_body",
        quote! {
            pub mod arm {
                pub struct Coords { pub q1: f64, pub q2: f64 }
                pub struct Arm { pub m: f64, pub l: f64, pub c: f64, pub ixx: f64, pub ixy: f64, pub izz: f64, pub k: f64 }
                #[rigid_body(mass = m, com = vec3(0.0, 0.0, c), inertia = [[ixx, ixy, 0.0], [ixy, ixx, 0.0], [0.0, 0.0, izz]])]
                fn upper() -> Spatial { spatial(vec3(0.0, 0.0, 0.0), rot_z(q1)) }
                #[rigid_body(mass = m, com = vec3(0.0, 0.0, c), inertia = [ixx, ixx, izz])]
                fn lower() -> Spatial {
                    upper.joint(vec3(0.0, 0.0, l), rot3([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]]) * rot_axis(vec3(0.0, 1.0, 0.0), q2))
                }
                #[potential]
                fn spring() -> f64 { 0.5 * k * lower.position.norm_squared() }
            }
        },
    );
    // Without the pretty-printer's line breaks.
    let out: String = out.split_whitespace().collect();
    assert!(out.contains("fn__lagrange_mass_frame_upper(&self,)"));
    assert!(out.contains("principal_axes(&__inertia_upper,).0"));
    assert!(out.contains(".__lagrange_mass_frame_upper().principal(__bodies.upper)"));
    assert!(out.contains("__frame_lower.frame("));
    assert!(out.contains("check_inertia_tensor(\"upper\""));
    assert!(out.contains("check_centre_of_mass(\"lower\""));
    assert!(out.contains("check_rotation(\"lower\""));
    assert!(out.contains("check_axis(\"lower\""));
    // Principal moments need no decomposition: the lower link's frame has no axes to turn.
    assert!(!out.contains("principal_axes(&__inertia_lower"));
}

/// A floating base as `#[lagrange::urdf(.., floating)]` writes it: the root's six consecutive
/// coordinates (origin, then modified Rodrigues parameters) are the runtime's free joint, and a
/// link hinged on it is placed from it as from any body.
#[test]
fn a_floating_base_takes_the_rigid_tree_pass_as_a_free_joint() {
    let out = snapshot(
        "floating_base",
        quote! {
            pub mod floating {
                pub struct Coords { pub base_position: [f64; 3], pub base_rotation: [f64; 3], pub q: f64 }
                pub struct Floating { pub m: f64, pub g: f64 }
                #[rigid_body(mass = m, inertia = [0.3, 0.2, 0.1])]
                fn base() -> Spatial {
                    spatial(
                        vec3(base_position[0], base_position[1], base_position[2]),
                        rot_mrp(vec3(base_rotation[0], base_rotation[1], base_rotation[2])),
                    )
                }
                #[rigid_body(mass = 0.5, inertia = [0.01, 0.01, 0.002])]
                fn leg() -> Spatial {
                    base.joint(vec3(0.2, 0.0, -0.1), rot_y(q))
                }
                #[gravity]
                fn down() -> Vec3 { vec3(0.0, 0.0, -g) }
            }
        },
    );
    let squeezed: String = out.split_whitespace().collect();
    assert!(out.contains("tree::rigid::RigidTree<7, 2> for Floating"));
    // The base: a root, free on coordinates 0..6, with no constant rotation or offset.
    assert!(squeezed.contains(
        "parent:::lagrange::__private::core::option::Option::None,kind:::lagrange::__private::tree::rigid::JointKind::Free(::lagrange::__private::lagrange_core::geometry::RotationChart::Mrp,::lagrange::__private::tree::rigid::Velocities::ChartRates,),coordinate:0,rotated:false,offset:[false,false,false],"
    ));
    // The leg: hinged on the base by coordinate 6.
    assert!(squeezed.contains(
        "parent:::lagrange::__private::core::option::Option::Some(0),kind:::lagrange::__private::tree::rigid::JointKind::Revolute(::lagrange::__private::tree::rigid::spatial::Axis::Y,),coordinate:6,"
    ));
    assert!(!out.contains("dynamics::equations_of_motion::<Self"));
}

/// A floating base placed by `pose`, with a leg on a hinge.
fn floating_with_base(pose: TokenStream) -> TokenStream {
    quote! {
        pub mod floating {
            pub struct Coords { pub p: [f64; 3], pub s: [f64; 3], pub q: f64 }
            pub struct Floating { pub m: f64, pub g: f64 }
            #[rigid_body(mass = m, inertia = [0.3, 0.2, 0.1])]
            fn base() -> Spatial { #pose }
            #[rigid_body(mass = 0.5, inertia = [0.01, 0.01, 0.002])]
            fn leg() -> Spatial { base.joint(vec3(0.2, 0.0, -0.1), rot_y(q)) }
            #[gravity]
            fn down() -> Vec3 { vec3(0.0, 0.0, -g) }
        }
    }
}

#[test]
fn a_floating_base_in_the_rotation_vector_is_a_free_joint_of_that_chart() {
    let pose = quote!(spatial(
        vec3(p[0], p[1], p[2]),
        rot_vector(vec3(s[0], s[1], s[2]))
    ));
    let out: String = pretty(expand(TokenStream::new(), floating_with_base(pose)))
        .split_whitespace()
        .collect();
    assert!(out.contains("tree::rigid::RigidTree<7,2>for"));
    assert!(out.contains(
        "kind:::lagrange::__private::tree::rigid::JointKind::Free(::lagrange::__private::lagrange_core::geometry::RotationChart::Vector,::lagrange::__private::tree::rigid::Velocities::ChartRates,),coordinate:0,"
    ));
    assert!(!out.contains("dynamics::equations_of_motion::<Self"));
}

#[test]
fn a_body_turning_about_a_fixed_point_is_a_ball_joint() {
    let module = quote! {
        pub mod top {
            pub struct Coords { pub s: [f64; 3] }
            pub struct Top { pub m: f64 }
            #[rigid_body(mass = m, inertia = [0.3, 0.3, 0.5])]
            fn top() -> Spatial {
                let r = rot_mrp(vec3(s[0], s[1], s[2]));
                spatial(vec3(0.0, 0.0, 0.5) + r * vec3(0.0, 0.0, 0.3), r)
            }
        }
    };
    let out: String = pretty(expand(TokenStream::new(), module))
        .split_whitespace()
        .collect();
    assert!(out.contains("tree::rigid::RigidTree<3,1>for"));
    // Its pivot is the offset r (only z can be non-zero), its centre of mass the body's own.
    assert!(out.contains(
        "kind:::lagrange::__private::tree::rigid::JointKind::Ball(::lagrange::__private::lagrange_core::geometry::RotationChart::Mrp,::lagrange::__private::tree::rigid::Velocities::ChartRates,),coordinate:0,rotated:false,offset:[false,false,true],"
    ));
    let constant = |name: &str| {
        let at = out.find(&format!("let{name}:Vec3<f64>=")).expect(name);
        out[at..at + out[at..].find(';').unwrap()].to_string()
    };
    assert!(
        constant("__offset").contains("vec3((0.0),(0.0),(0.5))"),
        "{}",
        constant("__offset")
    );
    assert!(
        constant("__own_0").contains("vec3((0.0),(0.0),(0.3))"),
        "{}",
        constant("__own_0")
    );
    assert!(!out.contains("dynamics::equations_of_motion::<Self"));
}

/// A body turned by a chart that the runtime's ball joint cannot take keeps the dense pass: a
/// constant rotation before the chart, a pivot that names a coordinate, a parent.
#[test]
fn a_turning_body_not_written_as_a_ball_root_keeps_the_dense_pass() {
    let top = |coords: TokenStream, pose: TokenStream| {
        quote! {
            pub mod top {
                pub struct Coords { #coords }
                pub struct Top { pub m: f64 }
                #[rigid_body(mass = m, inertia = [0.3, 0.3, 0.5])]
                fn link() -> Spatial { spatial(vec3(0.0, 0.0, 0.2), rot_y(h)) }
                #[rigid_body(mass = m, inertia = [0.3, 0.3, 0.5])]
                fn top() -> Spatial { #pose }
            }
        }
    };
    let (coords, with_z) = (
        quote!(pub h: f64, pub s: [f64; 3]),
        quote!(pub h: f64, pub s: [f64; 3], pub z: f64),
    );
    let cases = [
        (
            &coords,
            quote!(spatial(
                vec3(0.0, 0.0, 0.5),
                rot_x(0.1) * rot_vector(vec3(s[0], s[1], s[2]))
            )),
            "a constant rotation before the chart",
        ),
        (
            &with_z,
            quote!(spatial(
                vec3(0.0, 0.0, z),
                rot_vector(vec3(s[0], s[1], s[2]))
            )),
            "a pivot that names a coordinate",
        ),
        (
            &coords,
            quote!(spatial(
                link.point(vec3(0.0, 0.0, 0.5)),
                link.rotation * rot_vector(vec3(s[0], s[1], s[2]))
            )),
            "a parent",
        ),
    ];
    for (coords, pose, why) in cases {
        dense(top(coords.clone(), pose), why);
    }
    // The same declarations read as trees when the ball is a root written as one.
    let out = pretty(expand(
        TokenStream::new(),
        top(
            coords,
            quote!(spatial(
                vec3(0.0, 0.0, 0.5),
                rot_vector(vec3(s[0], s[1], s[2]))
            )),
        ),
    ));
    assert!(out.contains("JointKind::Ball"));
}

/// The declaration expands to the dense pass, not a rigid tree.
fn dense(module: TokenStream, why: &str) {
    let out: String = pretty(expand(TokenStream::new(), module))
        .split_whitespace()
        .collect();
    assert!(!out.contains("tree::rigid::RigidTree<"), "{why}");
    assert!(
        out.contains("dynamics::equations_of_motion::<Self"),
        "{why}"
    );
}

/// A free body the tree pass cannot take as the runtime's free joint keeps the dense pass: its six
/// coordinates out of order, a constant offset in the world frame or a constant rotation before
/// `rot_mrp` (the parameters before the origin, and a parent, below).
#[test]
fn a_free_body_not_written_as_a_free_root_keeps_the_dense_pass() {
    let cases = [
        (
            quote!(spatial(
                vec3(p[0], p[2], p[1]),
                rot_mrp(vec3(s[0], s[1], s[2]))
            )),
            "origin's coordinates out of order",
        ),
        (
            quote!(spatial(
                vec3(p[0], p[1], p[2]) + vec3(0.0, 0.0, 1.0),
                rot_mrp(vec3(s[0], s[1], s[2]))
            )),
            "a constant offset in the world frame",
        ),
        (
            quote!(spatial(
                vec3(p[0], p[1], p[2]),
                rot_x(0.1) * rot_mrp(vec3(s[0], s[1], s[2]))
            )),
            "a constant rotation before the parameters'",
        ),
    ];
    for (pose, why) in cases {
        dense(floating_with_base(pose), why);
    }
}

#[test]
fn a_free_body_with_its_parameters_before_its_origin_keeps_the_dense_pass() {
    // The parameters' coordinates before the origin's: were it taken for a free joint on the six
    // coordinates from the origin's, the base would claim a, b and c, the hinges s, and each
    // coordinate would move one node (the point moves no node): a wrong tree.
    dense(
        quote! {
            pub mod floating {
                pub struct Coords { pub s: [f64; 3], pub p: [f64; 3], pub a: f64, pub b: f64, pub c: f64 }
                pub struct Floating { pub m: f64 }
                #[rigid_body(mass = m, inertia = [0.3, 0.2, 0.1])]
                fn base() -> Spatial { spatial(vec3(p[0], p[1], p[2]), rot_mrp(vec3(s[0], s[1], s[2]))) }
                #[rigid_body(mass = 0.5, inertia = [0.01, 0.01, 0.002])]
                fn leg1() -> Spatial { base.joint(vec3(0.2, 0.0, -0.1), rot_y(s[0])) }
                #[rigid_body(mass = 0.5, inertia = [0.01, 0.01, 0.002])]
                fn leg2() -> Spatial { base.joint(vec3(-0.2, 0.0, -0.1), rot_y(s[1])) }
                #[rigid_body(mass = 0.5, inertia = [0.01, 0.01, 0.002])]
                fn leg3() -> Spatial { base.joint(vec3(0.0, 0.2, -0.1), rot_x(s[2])) }
                #[point]
                fn marker() -> Vec3 { vec3(a, b, c) }
            }
        },
        "the parameters' coordinates before the origin's",
    );
}

#[test]
fn a_free_body_with_a_parent_keeps_the_dense_pass() {
    // Free on a parent, in the parent's frame: the runtime's free joint is a root's.
    dense(
        quote! {
            pub mod floating {
                pub struct Coords { pub q: f64, pub p: [f64; 3], pub s: [f64; 3] }
                pub struct Floating { pub m: f64 }
                #[rigid_body(mass = m, inertia = [0.3, 0.2, 0.1])]
                fn link() -> Spatial { spatial(vec3(0.0, 0.0, 1.0), rot_z(q)) }
                #[rigid_body(mass = 0.5, inertia = [0.01, 0.01, 0.002])]
                fn rider() -> Spatial {
                    spatial(link.point(vec3(p[0], p[1], p[2])), link.rotation * rot_mrp(vec3(s[0], s[1], s[2])))
                }
            }
        },
        "a free body with a parent",
    );
}
