//! f64 4x4 matrix helpers for the benchmark scenes. Matrices are row-major
//! `m[row][col]` and act on column vectors (`p' = M p`), so `A * B` applies B
//! first — OpenGL's convention, written out by hand (no shared code with fixel).

/// A row-major 4x4 matrix acting on column vectors.
pub type Mat4 = [[f64; 4]; 4];

/// The identity matrix.
pub const IDENTITY: Mat4 = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// Matrix product `a * b`.
pub fn mul(a: &Mat4, b: &Mat4) -> Mat4 {
    core::array::from_fn(|r| core::array::from_fn(|c| (0..4).map(|k| a[r][k] * b[k][c]).sum()))
}

/// `m * v` for a column vector.
pub fn transform(m: &Mat4, v: [f64; 4]) -> [f64; 4] {
    core::array::from_fn(|r| (0..4).map(|k| m[r][k] * v[k]).sum())
}

/// The upper-left 3x3 of `m` applied to a direction (no translation).
pub fn transform_dir(m: &Mat4, d: [f64; 3]) -> [f64; 3] {
    core::array::from_fn(|r| (0..3).map(|k| m[r][k] * d[k]).sum())
}

/// Translation by `t`.
pub fn translation(t: [f64; 3]) -> Mat4 {
    let mut m = IDENTITY;
    for (r, row) in m.iter_mut().take(3).enumerate() {
        row[3] = t[r];
    }
    m
}

/// Right-handed rotation about +x by `a` radians (y turns towards z).
pub fn rotation_x(a: f64) -> Mat4 {
    let (s, c) = a.sin_cos();
    [
        [1.0, 0.0, 0.0, 0.0],
        [0.0, c, -s, 0.0],
        [0.0, s, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

/// Right-handed rotation about +y by `a` radians (z turns towards x).
pub fn rotation_y(a: f64) -> Mat4 {
    let (s, c) = a.sin_cos();
    [
        [c, 0.0, s, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [-s, 0.0, c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]
}

/// The `gluPerspective` matrix: vertical field of view `fovy_deg` degrees,
/// `aspect = width / height`, near and far plane distances (both > 0).
/// Maps eye z = -near to NDC z = -1 and eye z = -far to +1; clip w = -z_eye.
pub fn perspective(fovy_deg: f64, aspect: f64, near: f64, far: f64) -> Mat4 {
    let f = 1.0 / (fovy_deg.to_radians() / 2.0).tan();
    [
        [f / aspect, 0.0, 0.0, 0.0],
        [0.0, f, 0.0, 0.0],
        [
            0.0,
            0.0,
            (far + near) / (near - far),
            2.0 * far * near / (near - far),
        ],
        [0.0, 0.0, -1.0, 0.0],
    ]
}

/// `v / |v|`.
pub fn normalize(v: [f64; 3]) -> [f64; 3] {
    let n = dot(v, v).sqrt();
    v.map(|x| x / n)
}

/// Dot product.
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Cross product `a x b`.
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn perspective_maps_near_and_far_to_ndc_bounds() {
        let p = perspective(45.0, 4.0 / 3.0, 0.5, 20.0);
        let n = transform(&p, [0.0, 0.0, -0.5, 1.0]);
        let f = transform(&p, [0.0, 0.0, -20.0, 1.0]);
        assert!((n[2] / n[3] + 1.0).abs() < 1e-12);
        assert!((f[2] / f[3] - 1.0).abs() < 1e-12);
    }

    #[test]
    fn rotations_are_right_handed() {
        let y = transform(
            &rotation_y(core::f64::consts::FRAC_PI_2),
            [0.0, 0.0, 1.0, 0.0],
        );
        assert!((y[0] - 1.0).abs() < 1e-12);
        let x = transform(
            &rotation_x(core::f64::consts::FRAC_PI_2),
            [0.0, 1.0, 0.0, 0.0],
        );
        assert!((x[2] - 1.0).abs() < 1e-12);
    }
}
