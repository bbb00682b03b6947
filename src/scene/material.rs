//! `[[material]]` tables: the rules of each material type's keys (the keys themselves are
//! the models', `crate::material::Kind`), validated into `crate::material::MaterialModel`.

use super::check::{Context, unique_names};
use super::description::Material;
use super::error::SceneError;
use super::schema::RawMaterial;
use crate::material::{Kind, MaterialModel};
use std::path::Path;

pub(super) fn materials(path: &Path, raw: &[RawMaterial]) -> Result<Vec<Material>, SceneError> {
    if raw.is_empty() {
        let message = "the scene has no [[material]]";
        return Err(SceneError::new(path, "[[material]]", "", message));
    }
    unique_names(path, "material", raw.iter().map(|m| m.name.as_str()))?;
    let material = |(index, m): (usize, &RawMaterial)| {
        let at = Context::item(path, "material", &m.name, index);
        Ok(Material { name: m.name.clone(), model: material_model(&at, m)? })
    };
    raw.iter().enumerate().map(material).collect()
}

fn material_model(at: &Context, m: &RawMaterial) -> Result<MaterialModel, SceneError> {
    let Some(kind) = Kind::parse(&m.model) else {
        let known: Vec<String> = Kind::ALL.iter().map(|k| format!("\"{}\"", k.name())).collect();
        return Err(at.error("type", format!("unknown material type \"{}\"; known: {}", m.model, known.join(", "))));
    };
    let given = [
        ("reflectance", m.reflectance),
        ("transmittance", m.transmittance),
        ("specular", m.specular),
        ("exponent", m.exponent),
        ("roughness", m.roughness),
    ];
    for (key, value) in given {
        if value.is_some() && !kind.keys().contains(&key) {
            let message = format!("a \"{}\" material takes only {}", m.model, kind.keys().join(", "));
            return Err(at.error(key, message));
        }
    }
    let fraction = |key: &str, value: Option<f64>| -> Result<f64, SceneError> {
        let v = at.non_negative(key, value.unwrap_or(0.0))?;
        if v > 1.0 {
            return Err(at.error(key, format!("must be at most 1, got {v}")));
        }
        Ok(v)
    };
    let required = |key: &str, value: Option<f64>| {
        value.ok_or_else(|| at.error(key, format!("a \"{}\" material needs `{key}`", m.model)))
    };
    let reflectance = fraction("reflectance", Some(required("reflectance", m.reflectance)?))?;
    let sum_at_most_one = |key: &str, other: f64| {
        if reflectance + other > 1.0 + 1e-12 {
            return Err(at.error(key, format!("reflectance + {key} = {} exceeds 1", reflectance + other)));
        }
        Ok(())
    };
    Ok(match kind {
        Kind::Lambert => {
            let transmittance = fraction("transmittance", m.transmittance)?;
            sum_at_most_one("transmittance", transmittance)?;
            MaterialModel::Lambert { reflectance, transmittance }
        }
        Kind::Phong => {
            let specular = fraction("specular", Some(required("specular", m.specular)?))?;
            sum_at_most_one("specular", specular)?;
            let exponent = at.non_negative("exponent", required("exponent", m.exponent)?)?;
            if exponent > 1e5 {
                return Err(at.error("exponent", format!("must be at most 100000, got {exponent}")));
            }
            MaterialModel::Phong { diffuse: reflectance, specular, exponent }
        }
        Kind::Mirror => MaterialModel::Mirror { reflectance },
        Kind::Ggx => {
            let specular = fraction("specular", Some(required("specular", m.specular)?))?;
            sum_at_most_one("specular", specular)?;
            let roughness = fraction("roughness", Some(required("roughness", m.roughness)?))?;
            if roughness < 1e-3 {
                return Err(at.error("roughness", format!("must be at least 0.001 (use a mirror), got {roughness}")));
            }
            MaterialModel::Ggx { diffuse: reflectance, specular, roughness }
        }
    })
}
