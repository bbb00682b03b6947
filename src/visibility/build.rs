//! obvhs's binary tree over the triangles as its own builders make it before they turn it
//! into the layout their traversals read (spatial pre-splits, PLOC, reinsertion: the first
//! steps of `build_cwbvh_from_tris` and `build_bvh2_from_tris`), one (possibly split)
//! triangle a leaf: what ugo's four-wide [`Quad`](super::quad::Quad) is collapsed from.

use obvhs::{
    BvhBuildParams,
    aabb::Aabb,
    bvh2::{Bvh2, reinsertion::ReinsertionOptimizer},
    ploc::PlocBuilder,
    splits::split_aabbs_preset,
    triangle::Triangle,
};

/// obvhs's binary tree over `triangles`, one (possibly split) triangle a leaf.
pub fn binary_tree(triangles: &[Triangle], params: BvhBuildParams) -> Bvh2 {
    let mut bvh = if params.pre_split && !triangles.is_empty() {
        let mut aabbs: Vec<Aabb> = triangles.iter().map(|t| t.aabb()).collect();
        let largest = aabbs.iter().fold(0.0f32, |m, a| m.max(a.half_area()));
        let mean = aabbs.iter().map(|a| a.half_area()).sum::<f32>() / triangles.len() as f32;
        let mut indices: Vec<u32> = (0..triangles.len() as u32).collect();
        split_aabbs_preset(&mut aabbs, &mut indices, triangles, mean, largest);
        PlocBuilder::with_capacity(aabbs.len()).build(
            params.ploc_search_distance,
            &aabbs,
            indices,
            params.sort_precision,
            params.search_depth_threshold,
        )
    } else {
        PlocBuilder::with_capacity(triangles.len()).build(
            params.ploc_search_distance,
            triangles,
            (0..triangles.len() as u32).collect(),
            params.sort_precision,
            params.search_depth_threshold,
        )
    };
    bvh.uses_spatial_splits = params.pre_split;
    ReinsertionOptimizer::default().run(&mut bvh, params.reinsertion_batch_ratio, None);
    bvh
}
