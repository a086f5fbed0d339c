// The driver of a scene's page (rtfgu/browser/export.py writes the data it reads). It binds
// the buffers as rtfgu/wgsl/runner.py does: group 0 holds the Uniforms at binding 0 and the
// scene arrays at their numbers, group 1 the image sums. A frame adds one batch of samples
// to every tile, one dispatch (and one submit) per tile, each after writing its Uniforms,
// then draws the mean so far into the canvas (display.wgsl). Any GPU error ends the render
// and is shown as text.
//
// The worksheet's controls: the camera constant (zoom; a new value renders again), gamma
// (draws again) and, where the page holds several scenes, the shader menu. The query string
// sets them at the start (?zoom=1.5&gamma=1&scene=NAME); with ?report=URL the finished
// render is posted there as JSON.

const page = JSON.parse(document.getElementById("rtfgu-scene").textContent);
const displayWGSL = document.getElementById("rtfgu-display").textContent;
const statusLine = document.getElementById("status");
const canvas = document.getElementById("canvas");
const controls = document.getElementById("controls");
const query = new URLSearchParams(location.search);
const report = query.get("report");

class PageError extends Error {}

let scene = page.scenes[page.selected];
let failed = null;
let reported = false;

function show(text, isError) {
    statusLine.textContent = text;
    statusLine.className = isError ? "error" : "";
}

async function post(result) {
    if (reported) {
        return;
    }
    reported = true;
    if (report) {
        try {
            await fetch(report, {method: "POST", headers: {"Content-Type": "application/json"},
                                 body: JSON.stringify(result)});
        } catch (error) {
            show(statusLine.textContent + "\n(could not report to " + report + ": " + error + ")", true);
        }
    }
    if (window.parent !== window) {
        window.parent.postMessage({rtfguDone: scene.name}, "*");
    }
}

// The first error wins; it replaces the image by its text.
function fail(message) {
    if (failed !== null) {
        return;
    }
    failed = message;
    canvas.style.display = "none";
    controls.style.display = "none";
    show(message, true);
    post({ok: false, name: scene.name, message: message});
}

window.addEventListener("error", (event) => fail("JavaScript error: " + event.message));
window.addEventListener("unhandledrejection", (event) => fail("JavaScript error: " + event.reason));

function bytesOf(base64) {
    const text = atob(base64);
    const bytes = new Uint8Array(text.length);
    for (let i = 0; i < text.length; i++) {
        bytes[i] = text.charCodeAt(i);
    }
    return bytes;
}

function base64Of(buffer) {
    const bytes = new Uint8Array(buffer);
    let text = "";
    for (let i = 0; i < bytes.length; i += 0x8000) {
        text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    }
    return btoa(text);
}

// A compilation message at the file and line of rtfgu/wgsl it came from, as
// rtfgu/wgsl/runner.py's WGSLCompileError names it.
function describe(data, message) {
    const lines = data.wgsl.split("\n");
    const line = message.lineNum;
    let where = "line " + line + " of the assembled program";
    if (line >= 1 && line <= data.origins.lines.length) {
        const [file, fileLine] = data.origins.lines[line - 1];
        where = data.origins.files[file] + ":" + fileLine + ":" + message.linePos
              + " (line " + line + " of the assembled program)";
    }
    const text = line >= 1 && line <= lines.length ? "\n    " + lines[line - 1].trim() : "";
    return where + ": " + message.type + ": " + message.message + text;
}

async function checked(device, what, make) {
    device.pushErrorScope("validation");
    const made = make();
    const error = await device.popErrorScope();
    if (error) {
        throw new PageError(what + ": " + error.message);
    }
    return made;
}

async function openDevice() {
    if (!navigator.gpu) {
        throw new PageError("WebGPU is not available in this browser (navigator.gpu is missing): "
                            + "use a browser with WebGPU enabled, served over http://localhost or https");
    }
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) {
        throw new PageError("WebGPU found no adapter (navigator.gpu.requestAdapter() returned null)");
    }
    const device = await adapter.requestDevice();
    device.lost.then((info) => fail("GPU device lost (" + info.reason + "): " + info.message));
    device.addEventListener("uncapturederror", (event) => fail("GPU error: " + event.error.message));
    return device;
}

// The canvas and display.wgsl, which draws the mean of the sums in ``image`` with gamma.
async function openCanvas(device, image) {
    canvas.width = page.width;
    canvas.height = page.height;
    const scale = Math.max(1, Math.floor(512 / Math.max(page.width, page.height)));
    canvas.style.width = page.width * scale + "px";
    canvas.style.height = page.height * scale + "px";
    const context = canvas.getContext("webgpu");
    const format = navigator.gpu.getPreferredCanvasFormat();
    context.configure({device: device, format: format, alphaMode: "opaque",
                       usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC});
    const module = device.createShaderModule({label: "display.wgsl", code: displayWGSL});
    const layout = device.createBindGroupLayout({entries: [
        {binding: 0, visibility: GPUShaderStage.FRAGMENT, buffer: {type: "read-only-storage"}},
        {binding: 1, visibility: GPUShaderStage.FRAGMENT, buffer: {type: "uniform"}}]});
    const pipeline = await checked(device, "The canvas's render pipeline", () => device.createRenderPipeline({
        layout: device.createPipelineLayout({bindGroupLayouts: [layout]}),
        vertex: {module: module, entryPoint: "main_vs"},
        fragment: {module: module, entryPoint: "main_fs", targets: [{format: format}]},
        primitive: {topology: "triangle-list"}}));
    const uniforms = device.createBuffer({size: 16, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST});
    const group = device.createBindGroup({layout: layout, entries: [
        {binding: 0, resource: {buffer: image}}, {binding: 1, resource: {buffer: uniforms}}]});
    const bytesPerRow = Math.ceil(4 * page.width / 256) * 256;

    // Draws the mean of ``samples`` samples; with ``readBack``, also copies the canvas into
    // a buffer, returned, that ``pixels`` reads.
    function draw(samples, gamma, readBack) {
        const values = new ArrayBuffer(16);
        new Uint32Array(values, 0, 2).set([page.width, page.height]);
        new Float32Array(values, 8, 2).set([samples, gamma]);
        device.queue.writeBuffer(uniforms, 0, values);
        const texture = context.getCurrentTexture();
        const encoder = device.createCommandEncoder();
        const pass = encoder.beginRenderPass({colorAttachments: [{view: texture.createView(),
            loadOp: "clear", storeOp: "store", clearValue: [0, 0, 0, 1]}]});
        pass.setPipeline(pipeline);
        pass.setBindGroup(0, group);
        pass.draw(3);
        pass.end();
        let copy = null;
        if (readBack) {
            copy = device.createBuffer({size: bytesPerRow * page.height,
                                        usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ});
            encoder.copyTextureToBuffer({texture: texture}, {buffer: copy, bytesPerRow: bytesPerRow},
                                        [page.width, page.height]);
        }
        device.queue.submit([encoder.finish()]);
        return copy;
    }

    // The canvas's pixels as RGBA8, row 0 at the top.
    async function pixels(copy) {
        await copy.mapAsync(GPUMapMode.READ);
        const rows = new Uint8Array(copy.getMappedRange());
        const rgba = new Uint8Array(4 * page.width * page.height);
        const bgra = format.startsWith("bgra");
        for (let y = 0; y < page.height; y++) {
            for (let x = 0; x < page.width; x++) {
                const from = y * bytesPerRow + 4 * x, to = 4 * (y * page.width + x);
                rgba[to] = rows[from + (bgra ? 2 : 0)];
                rgba[to + 1] = rows[from + 1];
                rgba[to + 2] = rows[from + (bgra ? 0 : 2)];
                rgba[to + 3] = rows[from + 3];
            }
        }
        copy.unmap();
        return rgba;
    }
    return {draw: draw, pixels: pixels};
}

// The compiled program of one scene of the page, its buffers and bind group.
async function loadScene(device, data, imageLayout) {
    // The compilation messages name the line; the error scope keeps the same error from
    // also arriving, without a line, as an uncaptured error.
    device.pushErrorScope("validation");
    const module = device.createShaderModule({label: data.name, code: data.wgsl});
    const errors = (await module.getCompilationInfo()).messages.filter((m) => m.type === "error");
    const invalid = await device.popErrorScope();
    if (errors.length) {
        throw new PageError("The scene's WGSL did not compile:\n"
                            + errors.map((m) => describe(data, m)).join("\n"));
    }
    if (invalid) {
        throw new PageError("The scene's WGSL did not compile: " + invalid.message);
    }
    const compute = GPUShaderStage.COMPUTE;
    const sceneLayout = device.createBindGroupLayout({entries: [
        {binding: 0, visibility: compute, buffer: {type: "uniform"}},
        ...data.bindings.map((b) => ({binding: b.number, visibility: compute,
                                     buffer: {type: b.kind === "uniform" ? "uniform" : "read-only-storage"}}))]});
    const pipeline = await checked(device, "The scene's compute pipeline", () => device.createComputePipeline({
        layout: device.createPipelineLayout({bindGroupLayouts: [sceneLayout, imageLayout]}),
        compute: {module: module, entryPoint: "main"}}));
    const uniforms = device.createBuffer({size: data.uniforms_size,
                                          usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST});
    const buffers = {};
    const entries = [{binding: 0, resource: {buffer: uniforms}}];
    for (const b of data.bindings) {
        const bytes = bytesOf(b.data);
        const usage = b.kind === "uniform" ? GPUBufferUsage.UNIFORM : GPUBufferUsage.STORAGE;
        buffers[b.number] = {buffer: device.createBuffer({size: bytes.length, usage: usage | GPUBufferUsage.COPY_DST}),
                             bytes: bytes};
        device.queue.writeBuffer(buffers[b.number].buffer, 0, bytes);
        entries.push({binding: b.number, resource: {buffer: buffers[b.number].buffer}});
    }
    const group = device.createBindGroup({layout: sceneLayout, entries: entries});

    // The camera constant d (rtfgu.layout's camera record), written into the camera buffer.
    function setZoom(d) {
        if (!data.zoom) {
            return;
        }
        const camera = buffers[data.zoom.binding];
        const bytes = camera.bytes.slice();
        new DataView(bytes.buffer).setFloat32(4 * data.zoom.index, d, true);
        device.queue.writeBuffer(camera.buffer, 0, bytes);
    }
    return {data: data, pipeline: pipeline, group: group, uniforms: uniforms, setZoom: setZoom};
}

function addControl(label, element) {
    const wrapper = document.createElement("label");
    wrapper.append(label + " ", element);
    controls.append(wrapper);
    return element;
}

function numberInput(value, step, min) {
    const input = document.createElement("input");
    input.type = "number";
    input.step = step;
    input.min = min;
    input.value = value;
    input.style.width = "6em";
    return input;
}

async function start() {
    const device = await openDevice();
    const pixels = page.width * page.height;
    const image = device.createBuffer({size: 16 * pixels, usage: GPUBufferUsage.STORAGE
                                       | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST});
    const imageLayout = device.createBindGroupLayout({entries: [
        {binding: 0, visibility: GPUShaderStage.COMPUTE, buffer: {type: "storage"}}]});
    const imageGroup = device.createBindGroup({layout: imageLayout, entries: [
        {binding: 0, resource: {buffer: image}}]});
    const display = await openCanvas(device, image);

    const view = {gamma: parseFloat(query.get("gamma") || page.gamma), samples: 0,
                  zoom: query.get("zoom") === null ? null : parseFloat(query.get("zoom"))};
    if (query.get("scene") !== null) {
        scene = page.scenes.find((s) => s.name === query.get("scene"));
        if (!scene) {
            throw new PageError("?scene=" + query.get("scene") + ": this page holds "
                                + page.scenes.map((s) => s.name).join(", "));
        }
    }
    const loaded = {};
    let current = null;
    let generation = 0;

    async function sums() {
        const copy = device.createBuffer({size: 16 * pixels, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ});
        const encoder = device.createCommandEncoder();
        encoder.copyBufferToBuffer(image, 0, copy, 0, 16 * pixels);
        device.queue.submit([encoder.finish()]);
        await copy.mapAsync(GPUMapMode.READ);
        const data = copy.getMappedRange().slice(0);
        copy.unmap();
        return data;
    }

    // Renders the current scene from its first sample; a later call ends an earlier one.
    async function render() {
        const mine = ++generation;
        const started = performance.now();
        if (!(scene.name in loaded)) {
            show("compiling " + scene.name + "...", false);
            loaded[scene.name] = await loadScene(device, scene, imageLayout);
        }
        current = loaded[scene.name];
        current.setZoom(view.zoom === null ? scene.zoom?.value : view.zoom);
        device.queue.writeBuffer(image, 0, new Uint8Array(16 * pixels));
        view.samples = 0;
        const frames = current.data.frames;
        for (const frame of frames) {
            if (mine !== generation || failed !== null) {
                return;
            }
            for (const dispatch of frame.dispatches) {
                device.queue.writeBuffer(current.uniforms, 0, bytesOf(dispatch.uniforms));
                const encoder = device.createCommandEncoder();
                const pass = encoder.beginComputePass();
                pass.setPipeline(current.pipeline);
                pass.setBindGroup(0, current.group);
                pass.setBindGroup(1, imageGroup);
                pass.dispatchWorkgroups(dispatch.workgroups[0], dispatch.workgroups[1], 1);
                pass.end();
                device.queue.submit([encoder.finish()]);
            }
            view.samples = frame.end_sample;
            const last = frame === frames[frames.length - 1];
            const copy = display.draw(view.samples, view.gamma, last && !reported);
            await device.queue.onSubmittedWorkDone();
            if (failed !== null) {
                return;
            }
            const seconds = (performance.now() - started) / 1000;
            show(view.samples + " / " + current.data.samples + " samples per pixel, " + seconds.toFixed(1) + " s", false);
            if (copy) {
                const result = {ok: true, name: scene.name, width: page.width, height: page.height,
                                samples: view.samples, gamma: view.gamma, sums: base64Of(await sums()),
                                canvas: base64Of((await display.pixels(copy)).buffer), seconds: seconds};
                if (failed === null) {
                    await post(result);
                }
            }
            await new Promise((resolve) => setTimeout(resolve, 0));  // let the page show the frame
        }
    }

    const rerender = () => render().catch((error) => fail(error instanceof PageError ? error.message
                                                                             : "JavaScript error: " + error));
    if (page.scenes.length > 1) {
        const menu = document.createElement("select");
        for (const s of page.scenes) {
            menu.add(new Option(s.name, s.name, false, s === scene));
        }
        menu.addEventListener("change", () => {
            scene = page.scenes.find((s) => s.name === menu.value);
            rerender();
        });
        addControl(page.menu, menu);
    }
    if (scene.zoom) {
        const zoom = addControl("zoom (camera constant d)",
                                numberInput(view.zoom === null ? scene.zoom.value : view.zoom, 0.1, 0.1));
        zoom.addEventListener("change", () => {
            const d = parseFloat(zoom.value);
            if (d > 0) {
                view.zoom = d;
                rerender();
            }
        });
    }
    const gamma = addControl("gamma", numberInput(view.gamma, 0.1, 0.1));
    gamma.addEventListener("change", () => {
        const g = parseFloat(gamma.value);
        if (g > 0) {
            view.gamma = g;
            display.draw(view.samples, view.gamma, false);
        }
    });
    await render();
}

start().catch((error) => fail(error instanceof PageError ? error.message : "JavaScript error: " + error));
