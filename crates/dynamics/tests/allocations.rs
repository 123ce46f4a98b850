//! A collision allocates heap memory only while it is set up, not per solver step: the number of
//! allocations is the same for collisions of a few hundred and over a thousand steps. (The
//! Jacobian is assembled through diffsol's coloring path, which reuses scratch vectors; its
//! default path allocated two vectors per Jacobian evaluation.)

#![allow(clippy::unwrap_used, clippy::expect_used)]
#![allow(unsafe_code)] // a counting global allocator

use contact::{Contact, Geometry, Material};
use dynamics::{Collider, SolverOptions};
use greenwood::CrackLaw;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn allocations_do_not_grow_with_steps() {
    let law = CrackLaw::new(0.01).unwrap();
    let c = Contact::new(Material::co2(), Geometry::identical(60e-6)).unwrap();
    let opts = SolverOptions::default();
    let mut rows = Vec::new();
    for (t_vis, v_in, rtol) in [
        (1e-9, 0.045, 1e-6),
        (1e-9, 0.045, 1e-10),
        (1e-14, 0.0165, 1e-10),
    ] {
        let col = Collider::new(c, &law, t_vis)
            .unwrap()
            .with_options(SolverOptions {
                rtol,
                atol: 1e-3 * rtol,
                ..opts
            })
            .unwrap();
        col.collide(v_in).unwrap(); // warm up
        let before = ALLOCATIONS.load(Ordering::Relaxed);
        let r = col.collide(v_in).unwrap();
        let n = ALLOCATIONS.load(Ordering::Relaxed) - before;
        rows.push((r.steps, n));
    }
    eprintln!("(steps, allocations): {rows:?}");
    let (few, many) = (rows[0], rows[2]);
    assert!(many.0 > 3 * few.0, "{rows:?}");
    // per-step allocations would add at least one allocation per step
    assert!(
        many.1 < few.1 + many.0 / 10,
        "allocations grow with steps: {rows:?}"
    );
}
