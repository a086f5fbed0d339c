// The driver of a scene's page (rtfgu/browser/export.py writes the data it reads). It binds
// the buffers as rtfgu/wgsl/runner.py does: group 0 holds the Uniforms at binding 0 and the
// scene arrays at their numbers, group 1 the image sums. A frame adds one batch of samples
// to every tile, one dispatch (and one submit) per tile, each after writing its Uniforms,
// then draws the mean so far into the canvas (display.wgsl). Any GPU error ends the render
// and is shown as text. With ?report=URL the result is posted there as JSON.

const scene = JSON.parse(document.getElementById("rtfgu-scene").textContent);
const displayWGSL = document.getElementById("rtfgu-display").textContent;
const statusLine = document.getElementById("status");
const canvas = document.getElementById("canvas");
const report = new URLSearchParams(location.search).get("report");
const started = performance.now();

class PageError extends Error {}

let failed = null;
let finished = false;

function show(text, isError) {
    statusLine.textContent = text;
    statusLine.className = isError ? "error" : "";
}

async function post(result) {
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
    if (failed !== null || finished) {
        return;
    }
    failed = message;
    canvas.style.display = "none";
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
function describe(message) {
    const lines = scene.wgsl.split("\n");
    const line = message.lineNum;
    let where = "line " + line + " of the assembled program";
    if (line >= 1 && line <= scene.origins.lines.length) {
        const [file, fileLine] = scene.origins.lines[line - 1];
        where = scene.origins.files[file] + ":" + fileLine + ":" + message.linePos
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

async function start() {
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

    // The compilation messages name the line; the error scope keeps the same error from
    // also arriving, without a line, as an uncaptured error.
    device.pushErrorScope("validation");
    const module = device.createShaderModule({label: scene.name, code: scene.wgsl});
    const errors = (await module.getCompilationInfo()).messages.filter((m) => m.type === "error");
    const invalid = await device.popErrorScope();
    if (errors.length) {
        throw new PageError("The scene's WGSL did not compile:\n" + errors.map(describe).join("\n"));
    }
    if (invalid) {
        throw new PageError("The scene's WGSL did not compile: " + invalid.message);
    }
    const compute = GPUShaderStage.COMPUTE;
    const sceneLayout = device.createBindGroupLayout({entries: [
        {binding: 0, visibility: compute, buffer: {type: "uniform"}},
        ...scene.bindings.map((b) => ({binding: b.number, visibility: compute,
                                      buffer: {type: b.kind === "uniform" ? "uniform" : "read-only-storage"}}))]});
    const imageLayout = device.createBindGroupLayout({entries: [
        {binding: 0, visibility: compute | GPUShaderStage.FRAGMENT, buffer: {type: "storage"}}]});
    const pipeline = await checked(device, "The scene's compute pipeline", () => device.createComputePipeline({
        layout: device.createPipelineLayout({bindGroupLayouts: [sceneLayout, imageLayout]}),
        compute: {module: module, entryPoint: "main"}}));

    const uniforms = device.createBuffer({size: scene.uniforms_size,
                                          usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST});
    const buffers = {};
    const entries = [{binding: 0, resource: {buffer: uniforms}}];
    for (const b of scene.bindings) {
        const data = bytesOf(b.data);
        const usage = b.kind === "uniform" ? GPUBufferUsage.UNIFORM : GPUBufferUsage.STORAGE;
        buffers[b.name] = device.createBuffer({size: data.length, usage: usage | GPUBufferUsage.COPY_DST});
        device.queue.writeBuffer(buffers[b.name], 0, data);
        entries.push({binding: b.number, resource: {buffer: buffers[b.name]}});
    }
    const sceneGroup = device.createBindGroup({layout: sceneLayout, entries: entries});
    const pixels = scene.width * scene.height;
    const image = device.createBuffer({size: 16 * pixels, usage: GPUBufferUsage.STORAGE
                                       | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST});
    const imageGroup = device.createBindGroup({layout: imageLayout, entries: [
        {binding: 0, resource: {buffer: image}}]});

    // The canvas: display.wgsl draws the sums' mean with gamma.
    canvas.width = scene.width;
    canvas.height = scene.height;
    const scale = Math.max(1, Math.floor(512 / Math.max(scene.width, scene.height)));
    canvas.style.width = scene.width * scale + "px";
    canvas.style.height = scene.height * scale + "px";
    const context = canvas.getContext("webgpu");
    const format = navigator.gpu.getPreferredCanvasFormat();
    context.configure({device: device, format: format, alphaMode: "opaque",
                       usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC});
    const displayModule = device.createShaderModule({label: "display.wgsl", code: displayWGSL});
    const displayLayout = device.createBindGroupLayout({entries: [
        {binding: 0, visibility: GPUShaderStage.FRAGMENT, buffer: {type: "read-only-storage"}},
        {binding: 1, visibility: GPUShaderStage.FRAGMENT, buffer: {type: "uniform"}}]});
    const displayPipeline = await checked(device, "The canvas's render pipeline", () => device.createRenderPipeline({
        layout: device.createPipelineLayout({bindGroupLayouts: [displayLayout]}),
        vertex: {module: displayModule, entryPoint: "main_vs"},
        fragment: {module: displayModule, entryPoint: "main_fs", targets: [{format: format}]},
        primitive: {topology: "triangle-list"}}));
    const displayUniforms = device.createBuffer({size: 16, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST});
    const displayGroup = device.createBindGroup({layout: displayLayout, entries: [
        {binding: 0, resource: {buffer: image}}, {binding: 1, resource: {buffer: displayUniforms}}]});

    const view = {gamma: scene.gamma, samples: 0};

    // Draws the mean of the sums into the canvas; with ``readBack``, also copies the
    // canvas into a buffer mapped for reading (returned).
    function draw(readBack) {
        const values = new ArrayBuffer(16);
        new Uint32Array(values, 0, 2).set([scene.width, scene.height]);
        new Float32Array(values, 8, 2).set([view.samples, view.gamma]);
        device.queue.writeBuffer(displayUniforms, 0, values);
        const texture = context.getCurrentTexture();
        const encoder = device.createCommandEncoder();
        const pass = encoder.beginRenderPass({colorAttachments: [{view: texture.createView(),
            loadOp: "clear", storeOp: "store", clearValue: [0, 0, 0, 1]}]});
        pass.setPipeline(displayPipeline);
        pass.setBindGroup(0, displayGroup);
        pass.draw(3);
        pass.end();
        let copy = null;
        const bytesPerRow = Math.ceil(4 * scene.width / 256) * 256;
        if (readBack) {
            copy = device.createBuffer({size: bytesPerRow * scene.height,
                                        usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ});
            encoder.copyTextureToBuffer({texture: texture}, {buffer: copy, bytesPerRow: bytesPerRow},
                                        [scene.width, scene.height]);
        }
        device.queue.submit([encoder.finish()]);
        return {buffer: copy, bytesPerRow: bytesPerRow};
    }

    // The canvas's pixels as RGBA8, row 0 at the top.
    async function canvasPixels(copy) {
        await copy.buffer.mapAsync(GPUMapMode.READ);
        const rows = new Uint8Array(copy.buffer.getMappedRange());
        const rgba = new Uint8Array(4 * pixels);
        const bgra = format.startsWith("bgra");
        for (let y = 0; y < scene.height; y++) {
            for (let x = 0; x < scene.width; x++) {
                const from = y * copy.bytesPerRow + 4 * x, to = 4 * (y * scene.width + x);
                rgba[to] = rows[from + (bgra ? 2 : 0)];
                rgba[to + 1] = rows[from + 1];
                rgba[to + 2] = rows[from + (bgra ? 0 : 2)];
                rgba[to + 3] = rows[from + 3];
            }
        }
        copy.buffer.unmap();
        return rgba;
    }

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

    for (const frame of scene.frames) {
        for (const dispatch of frame.dispatches) {
            device.queue.writeBuffer(uniforms, 0, bytesOf(dispatch.uniforms));
            const encoder = device.createCommandEncoder();
            const pass = encoder.beginComputePass();
            pass.setPipeline(pipeline);
            pass.setBindGroup(0, sceneGroup);
            pass.setBindGroup(1, imageGroup);
            pass.dispatchWorkgroups(dispatch.workgroups[0], dispatch.workgroups[1], 1);
            pass.end();
            device.queue.submit([encoder.finish()]);
        }
        view.samples = frame.end_sample;
        const last = frame === scene.frames[scene.frames.length - 1];
        const copy = draw(last);
        await device.queue.onSubmittedWorkDone();
        if (failed !== null) {
            return;
        }
        const seconds = (performance.now() - started) / 1000;
        show(view.samples + " / " + scene.samples + " samples per pixel, " + seconds.toFixed(1) + " s", false);
        if (last) {
            const result = {ok: true, name: scene.name, width: scene.width, height: scene.height,
                            samples: view.samples, sums: base64Of(await sums()),
                            canvas: base64Of((await canvasPixels(copy)).buffer), seconds: seconds};
            if (failed === null) {
                finished = true;
                await post(result);
            }
        }
        await new Promise((resolve) => setTimeout(resolve, 0));  // let the page show the frame
    }
}

start().catch((error) => fail(error instanceof PageError ? error.message : "JavaScript error: " + error));
