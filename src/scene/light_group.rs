//! Light groups: `light_group { OBJECTS.. LIGHTS.. [global_lights on|off] }`.
//!
//! In: nothing (data definition). Out: [`LightGroup`], the group a surface belongs to, and
//! the rule saying which lights light which surfaces, and the renumbering that makes each
//! placement of a declared group a group of its own. Holds: group ids are unique within
//! one scene; a light's group is `None` for the scene's ordinary (global) lights.

use super::{Object, Shape};

/// The light group an object's surfaces belong to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct LightGroup {
    /// The group's id, shared with the lights written inside it.
    pub id: u32,
    /// `global_lights on`: the scene's own lights light the group's objects too.
    pub global_lights: bool,
}

impl LightGroup {
    /// Whether a light of group `light` (`None`: a scene light) lights a surface of group
    /// `surface` (`None`: an object outside every group). Group lights light only their
    /// group; scene lights light every surface outside groups and the surfaces of groups
    /// with `global_lights on`.
    pub fn lights(light: Option<u32>, surface: Option<LightGroup>) -> bool {
        match (light, surface) {
            (None, None) => true,
            (None, Some(group)) => group.global_lights,
            (Some(_), None) => false,
            (Some(id), Some(group)) => id == group.id,
        }
    }
}

/// Gives every light group in `object`'s tree a fresh id (taken from `last_id`, the
/// largest id handed out so far) and moves the group's lights to it. POV-Ray makes each
/// placement of a declared `light_group` a group of its own (measured: two placements
/// light each other's objects in durer before this, not in POV-Ray), so an object is
/// renumbered whenever it joins the scene.
pub fn separate_light_groups(object: &mut Object, last_id: &mut u32) {
    if let Some(group) = &mut object.light_group {
        *last_id += 1;
        let old = group.id;
        group.id = *last_id;
        move_group_lights(object, old, *last_id);
    }
    if let Shape::Csg { children, .. } = &mut object.shape {
        for child in children {
            separate_light_groups(child, last_id);
        }
    }
}

/// Moves the lights of group `old` in `object`'s tree to group `new`.
fn move_group_lights(object: &mut Object, old: u32, new: u32) {
    for light in object
        .lights
        .iter_mut()
        .flat_map(|lights| lights.iter_mut())
    {
        if light.group == Some(old) {
            light.group = Some(new);
        }
    }
    if let Shape::Csg { children, .. } = &mut object.shape {
        for child in children {
            move_group_lights(child, old, new);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lights_stay_in_their_group() {
        let closed = LightGroup {
            id: 1,
            global_lights: false,
        };
        let open = LightGroup {
            id: 2,
            global_lights: true,
        };
        assert!(LightGroup::lights(None, None));
        assert!(!LightGroup::lights(None, Some(closed)));
        assert!(LightGroup::lights(None, Some(open)));
        assert!(!LightGroup::lights(Some(1), None));
        assert!(LightGroup::lights(Some(1), Some(closed)));
        assert!(!LightGroup::lights(Some(1), Some(open)));
    }

    /// A group (id 1) holding one light of its own.
    fn group_with_light() -> Object {
        let mut group = Object::new(Shape::Csg {
            operation: crate::scene::CsgOperation::Union,
            children: Vec::new(),
        });
        group.light_group = Some(LightGroup {
            id: 1,
            global_lights: false,
        });
        let mut light = crate::scene::LightSource::point(glam::DVec3::ZERO, glam::DVec3::ONE);
        light.group = Some(1);
        group.lights = Some(Box::new(vec![light]));
        group
    }

    #[test]
    fn each_placement_is_a_group_of_its_own() {
        let mut last_id = 1;
        let mut placements = [group_with_light(), group_with_light()];
        for placement in &mut placements {
            separate_light_groups(placement, &mut last_id);
        }
        for (placement, id) in placements.iter().zip([2, 3]) {
            assert_eq!(placement.light_group.map(|g| g.id), Some(id));
            let lights = placement.lights.as_deref().unwrap();
            assert_eq!(lights[0].group, Some(id));
        }
    }
}
