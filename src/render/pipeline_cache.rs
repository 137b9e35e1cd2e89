//! Pipelines built once per key, under error checks, from shader modules composed once.
//!
//! Every renderer whose pipelines depend on the frame (the display's K and N, a scene option)
//! keeps them here, keyed by a named struct: [`crate::render::Renderer::prepare`] builds what a
//! frame needs, `encode` only looks it up.

use std::collections::HashMap;
use std::hash::Hash;

use crate::error::{Error, Result};

/// Shader modules by stage path (`wgsl/…`), each composed and created once.
#[derive(Default)]
pub(crate) struct ShaderModules {
    modules: HashMap<&'static str, wgpu::ShaderModule>,
}

impl ShaderModules {
    /// The module of `stage`, created on first use.
    pub fn get(
        &mut self,
        device: &wgpu::Device,
        stage: &'static str,
    ) -> Result<wgpu::ShaderModule> {
        if let Some(module) = self.modules.get(stage) {
            return Ok(module.clone());
        }
        let module = crate::shader::module(device, stage)?;
        self.modules.insert(stage, module.clone());
        Ok(module)
    }
}

/// Pipelines of type `P` by key `K`.
pub(crate) struct PipelineCache<K, P> {
    /// What the pipelines are, for errors ("building the … pipelines").
    what: &'static str,
    modules: ShaderModules,
    built: HashMap<K, P>,
}

impl<K: Copy + Eq + Hash, P> PipelineCache<K, P> {
    pub fn new(what: &'static str) -> Self {
        Self {
            what,
            modules: ShaderModules::default(),
            built: HashMap::new(),
        }
    }

    /// Build the pipelines for `key` unless they exist, inside validation and out-of-memory
    /// error scopes (a failure is `Error::Gpu` naming them, not wgpu's panic).
    pub fn prepare(
        &mut self,
        device: &wgpu::Device,
        key: K,
        build: impl FnOnce(&mut ShaderModules) -> Result<P>,
    ) -> Result<&P> {
        if !self.built.contains_key(&key) {
            let modules = &mut self.modules;
            let operation = format!("building the {} pipelines", self.what);
            let pipelines = crate::gpu::checked(device, &operation, || build(modules))??;
            self.built.insert(key, pipelines);
        }
        Ok(&self.built[&key])
    }

    /// The pipelines [`PipelineCache::prepare`] built for `key`; `Err(NotPrepared)` where it
    /// built none (encode without the prepare of its frame), never a panic.
    pub fn get(&self, key: &K) -> Result<&P>
    where
        K: std::fmt::Debug,
    {
        self.built.get(key).ok_or_else(|| Error::NotPrepared {
            renderer: self.what,
            frame: format!("pipelines for {key:?}"),
            prepared: format!("pipelines for {} other keys", self.built.len()),
        })
    }
}
