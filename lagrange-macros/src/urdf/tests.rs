//! The declarations written for the repository's test files, checked by eye and by the
//! integration tests; here, compared with their snapshots, and the refusals name their element.

use super::*;

fn written(file: &str) -> String {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/urdf/");
    let path: syn::LitStr = syn::parse_str(&format!("\"{dir}{file}\"")).unwrap();
    let module: syn::ItemMod = syn::parse_str("pub mod m {}").unwrap();
    match declaration(&path, false, &module) {
        Ok(t) => match syn::parse2(t.clone()) {
            Ok(file) => prettyplease::unparse(&file),
            Err(e) => format!("{e}: {t}"),
        },
        Err(e) => e,
    }
}

#[test]
#[ignore]
fn print() {
    println!("{}", written(&std::env::var("URDF_FILE").unwrap()));
}

#[test]
fn refusals_name_the_element_or_the_position() {
    let cases = [
        ("bad/mimic.urdf", "joint `finger_joint` is a mimic joint"),
        ("bad/floating.urdf", "joint `free_flyer` is floating"),
        (
            "bad/two_parents.urdf",
            "link `arm` has two parents, by joints `a` and `c`",
        ),
        (
            "bad/loop.urdf",
            "the joints form a loop through link `other`",
        ),
        (
            "bad/name_clash.urdf",
            "joint `wrist_1` and joint `wrist-1` both become `wrist_1`",
        ),
        (
            "bad/massless_link.urdf",
            "link `gimbal`, moved by joint `pan`, has no mass",
        ),
        ("bad/bad_xml.urdf", ":6:3: expected 'link' tag, not 'lnk'"),
        (
            "bad/missing_attribute.urdf",
            ":7:7: `<inertia>` has no `izz` attribute",
        ),
        (
            "bad/not_a_number.urdf",
            ":9:5: `xyz` of `<origin>` is not a finite number: `heavy`",
        ),
        ("bad/no_such_file.urdf", "cannot read the URDF file `"),
    ];
    for (file, expected) in cases {
        let message = written(file);
        assert!(message.contains(expected), "{file}: {message}");
    }
}

/// The declarations written for the test files, compared with the snapshots
/// `tests/expand/urdf_<file>.declaration.rs` (the file's directory written as `tests/urdf/`).
#[test]
fn the_test_files_are_written_as_their_snapshots() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/urdf/");
    for name in ["two_link_arm", "branched", "every_joint"] {
        let text = written(&format!("{name}.urdf")).replace(dir, "tests/urdf/");
        crate::expand_tests::compare_with_snapshot(&format!("urdf_{name}.declaration.rs"), &text);
    }
}

/// The tree's refusals, on files written here: each names the link or joint at fault.
#[test]
fn refusals_of_the_tree_name_the_link_or_the_joint() {
    let link = |name: &str| {
        format!(
            r#"<link name="{name}"><inertial><mass value="1.0"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>"#
        )
    };
    let joint = |name: &str, kind: &str, parent: &str, child: &str| {
        format!(
            r#"<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/><axis xyz="0 0 1"/></joint>"#
        )
    };
    let cases = [
        (vec![link("a"), link("a")], "link `a` is declared twice"),
        (
            vec![
                link("a"),
                link("b"),
                link("c"),
                joint("j", "revolute", "a", "b"),
                joint("j", "revolute", "b", "c"),
            ],
            "joint `j` is declared twice",
        ),
        (
            vec![link("a"), link("b"), joint("j", "planar", "a", "b")],
            "joint `j` is planar, which is not supported",
        ),
        (
            vec![link("a"), joint("j", "revolute", "a", "b")],
            "joint `j` names link `b`, which the file does not declare",
        ),
        (vec![], "the file declares no link"),
        (
            vec![link("a"), link("b")],
            "links `a` and `b` both have no parent",
        ),
        (
            vec![
                link("a"),
                link("b"),
                joint("j", "revolute", "a", "b"),
                joint("k", "revolute", "b", "a"),
            ],
            "the joints form a loop (link `a` is its own ancestor)",
        ),
    ];
    for (elements, expected) in cases {
        let text = format!(
            r#"<?xml version="1.0"?><robot name="r">{}</robot>"#,
            elements.concat()
        );
        let robot = parse::parse(&text).unwrap_or_else(|e| panic!("{text}: {}", e.message));
        let message = tree::bodies(&robot, false).expect_err("a refusal");
        assert!(message.contains(expected), "{text}: {message}");
    }
}

/// Parts welded together keep their mass, first moment and inertia about any point: two point
/// masses 1 and 3 at x = 0 and x = 4 have their centre at 3 and, about it, the moment
/// 1·3² + 3·1² = 12 about y and z (none about x).
#[test]
fn welded_parts_combine_by_the_parallel_axis_theorem() {
    use frames::{combine, MassPart};
    let point = |mass, x| MassPart {
        mass,
        centre: [x, 0.0, 0.0],
        inertia: [[0.0; 3]; 3],
    };
    let whole = combine(&[point(1.0, 0.0), point(3.0, 4.0)]).unwrap();
    assert_eq!(whole.mass, 4.0);
    assert_eq!(whole.centre, [3.0, 0.0, 0.0]);
    assert_eq!(
        whole.inertia,
        [[0.0, 0.0, 0.0], [0.0, 12.0, 0.0], [0.0, 0.0, 12.0]]
    );
}

#[test]
fn names_become_identifiers() {
    assert_eq!(
        names::sanitise("Shoulder-Pan joint", "joint"),
        "shoulder_pan_joint"
    );
    assert_eq!(names::sanitise("1st", "link"), "link_1st");
    assert_eq!(names::sanitise("type", "joint"), "type_");
    assert_eq!(names::sanitise("_", "joint"), "__");
}
