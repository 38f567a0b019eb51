//! The declarations written for the repository's test files, checked by eye and by the
//! integration tests; here, that the refusals name their element.

use super::*;

fn written(file: &str) -> String {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/urdf/");
    let path: syn::LitStr = syn::parse_str(&format!("\"{dir}{file}\"")).unwrap();
    let module: syn::ItemMod = syn::parse_str("pub mod m {}").unwrap();
    match declaration(&path, &module) {
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
