//! The places of a mesh's leaves (`ugo::placement::places`, the classes of `ugo agree`'s
//! leaf-by-leaf table) on the room of this file's tests, at 0.1 m patches: the floor's
//! patch before the block's foot is a contact, its patch in the room's corner an edge,
//! its patch under the board (which hides the whole lamp from it) an umbra, an open patch
//! of the floor open, and the emitting lamp has no place.

use super::scene;
use glam::DVec3;
use ugo::geometry::Mesh;
use ugo::luminaire::Source;
use ugo::placement::{Place, places};
use ugo::trace::World;

#[test]
fn the_floor_s_leaves_lie_where_the_room_puts_them() {
    let scene = scene();
    let world = World::new(&scene, Mesh::build(&scene.surfaces, 0.1));
    let sources: Vec<Source> = scene.luminaires.iter().map(Source::of).collect();
    let placed = places(&world, &sources);
    let floor_at = |x: f64, z: f64| {
        let c = DVec3::new(x, 0.0, z);
        world
            .mesh
            .patches
            .iter()
            .position(|p| p.normal.y > 0.99 && p.centroid.distance(c) < 1e-9)
            .expect("a floor patch there")
    };
    for (x, z, place) in
        [(0.55, 0.25, Place::Contact), (0.05, 0.05, Place::Edge), (0.25, 0.75, Place::Umbra), (0.35, 0.25, Place::Open)]
    {
        assert_eq!(placed[floor_at(x, z)], Some(place), "the floor at ({x}, {z})");
    }
    let lamp = world.mesh.emission.iter().position(|&e| e > 0.0).expect("the lamp emits");
    assert_eq!(placed[lamp], None);
}
