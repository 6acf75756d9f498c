//! Materials and uv coordinates: texture, interior and flag inheritance down CSG, shared
//! converted textures with pattern transforms mapped to world space, shadow queries skipping
//! `no_shadow`, and the lathe's and sor's uv parametrisations.

use super::support::{csg, marked, scene_of};
use crate::geometry::{Ray, World};
use crate::math::{Colour, Transform};
use crate::{
    scene::{CsgOperation, Interior, Object, Shape},
    texture::{
        pattern::{Pattern, PatternKind},
        Pigment, PigmentMap, Texture,
    },
};
use glam::{DVec2, DVec3};
use std::sync::Arc;

#[test]
fn materials_inherit_and_share_textures() {
    let checker = Pigment::Pattern {
        pattern: Box::new(Pattern::new(PatternKind::Checker)),
        map: PigmentMap::Blocks(vec![
            Pigment::Solid(Colour::WHITE),
            Pigment::Pattern {
                pattern: Box::new(Pattern::new(PatternKind::Gradient(DVec3::Y))),
                map: PigmentMap::Colours(vec![(0.0, Colour::BLACK), (1.0, Colour::WHITE)]),
                transform: Transform::translation(DVec3::Y),
            },
        ]),
        transform: Transform::scaling(DVec3::splat(0.5)).unwrap(),
    };
    let owner_texture = Arc::new(Texture {
        pigment: checker,
        ..Texture::default()
    });
    let first = Object::new(Shape::Sphere {
        centre: DVec3::ZERO,
        radius: 1.0,
    });
    let mut second = Object::new(Shape::Sphere {
        centre: DVec3::X * 3.0,
        radius: 1.0,
    });
    second.no_shadow = true;
    let mut own = marked(
        Shape::Sphere {
            centre: DVec3::X * 6.0,
            radius: 1.0,
        },
        0.5,
    );
    own.interior = Some(Box::new(Interior {
        ior: 2.0,
        ..Interior::default()
    }));
    let mut group = csg(CsgOperation::Union, vec![first, second, own]);
    group.texture = Some(owner_texture);
    group.interior = Some(Box::new(Interior {
        ior: 1.5,
        ..Interior::default()
    }));
    let world_from_group = Transform::translation(DVec3::new(0.0, 0.0, 10.0));
    group.set_transform(world_from_group);
    let plain = Object::new(Shape::Sphere {
        centre: DVec3::Y * 5.0,
        radius: 1.0,
    });
    let world = World::build(&scene_of(vec![group, plain]));
    assert_eq!(world.object_count(), 4);
    let hit_at = |x: f64, y: f64| {
        let ray = Ray::new(DVec3::new(x, y, 0.0), DVec3::Z);
        world.first_hit(&ray, 0.0, f64::INFINITY).unwrap()
    };
    let first_material = &world.materials[hit_at(0.0, 0.0).material as usize];
    let second_material = &world.materials[hit_at(3.0, 0.0).material as usize];
    let own_material = &world.materials[hit_at(6.0, 0.0).material as usize];
    let plain_material = &world.materials[world
        .first_hit(
            &Ray::new(DVec3::new(0.0, 5.0, -5.0), DVec3::Z),
            0.0,
            f64::INFINITY,
        )
        .unwrap()
        .material as usize];
    // Both children inherit one converted texture, shared.
    assert!(Arc::ptr_eq(
        &first_material.texture,
        &second_material.texture
    ));
    assert_eq!(first_material.interior.ior, 1.5);
    assert!(!first_material.no_shadow);
    assert!(second_material.no_shadow);
    assert_eq!(own_material.interior.ior, 2.0);
    assert!(matches!(own_material.texture.pigment, Pigment::Solid(_)));
    assert_eq!(plain_material.interior.ior, 1.0);
    assert!(matches!(plain_material.texture.pigment, Pigment::Solid(c) if c == Colour::BLACK));
    // Pattern transforms now map pattern space to world space, in nested block maps too.
    let Pigment::Pattern {
        transform,
        map: PigmentMap::Blocks(blocks),
        ..
    } = &first_material.texture.pigment
    else {
        panic!("expected the checker pattern");
    };
    let expected = Transform::scaling(DVec3::splat(0.5))
        .unwrap()
        .then(&world_from_group);
    assert_eq!(*transform, expected);
    assert_eq!(
        transform.point_to_outer(DVec3::ONE),
        DVec3::new(0.5, 0.5, 10.5)
    );
    let Pigment::Pattern {
        transform: inner, ..
    } = &blocks[1]
    else {
        panic!("expected the gradient block");
    };
    assert_eq!(
        *inner,
        Transform::translation(DVec3::Y).then(&world_from_group)
    );
    // Shadow queries skip the shadowless child.
    let through = Ray::new(DVec3::new(3.0, 0.0, 0.0), DVec3::Z);
    assert!(world.first_hit(&through, 0.0, f64::INFINITY).is_some());
    assert!(world
        .first_shadow_hit(&through, 0.0, f64::INFINITY)
        .is_none());
}

#[test]
fn lathe_and_sor_uv_follow_pov_ray() {
    use crate::geometry::lathe::Lathe;
    use crate::geometry::sor::Sor;
    // One straight segment from (r, y) = (1, 0) to (1, 1): v is the height's share.
    let third = |t: f64| DVec2::new(1.0, t);
    let lathe =
        Lathe::new(&[[third(0.0), third(1.0 / 3.0), third(2.0 / 3.0), third(1.0)]]).unwrap();
    let uv = lathe.uv(DVec3::new(0.0, 0.5, -1.0), 0);
    assert!((uv - DVec2::new(0.75, 0.5)).abs().max_element() < 1e-9);
    // A sor of radius 1 from y = 0 to 1: the side by height, the top cap by radius.
    let points = [
        DVec2::new(1.0, -1.0),
        DVec2::new(1.0, 0.0),
        DVec2::new(1.0, 1.0),
        DVec2::new(1.0, 2.0),
    ];
    let sor = Sor::new(&points, false).unwrap();
    let side = sor.uv(DVec3::new(1.0, 0.25, 0.0), 2);
    assert!((side - DVec2::new(0.0, 0.25)).abs().max_element() < 1e-9);
    let top = sor.uv(DVec3::new(0.0, 1.0, 0.5), 1);
    assert!((top - DVec2::new(0.25, 0.5)).abs().max_element() < 1e-9);
    let bottom = sor.uv(DVec3::new(-0.5, 0.0, 0.0), 0);
    assert!((bottom - DVec2::new(0.5, 0.5)).abs().max_element() < 1e-9);
}
