"""Type each inlined overload once per signature.

The kernels pick a kind's code at compile time through overloads with ``inline="always"``
(rtfgu.kernels.dispatch ``_overloaded``): the body for a kind the scene has, another for a
kind it lacks. numba (0.68.1, the version read) types such an overload's body again at every call of its
template (``_OverloadFunctionTemplate.generic``, numba/core/typing/templates.py): once per
call site and once more at every round of type propagation that revisits the call, with
the same argument types each time. In a render kernel the light loop was typed 7 times and
each shape kind's shadow test 25 times, for the same signature: most of a kernel's compile.

What stays is one typing per signature, plus one per call site when the typed inliner
puts the body in (``InlineWorker.update_type_and_call_maps`` types each copy under its new
variable names). ``cache_inline_typing()`` keeps the first typing of each (template, typing context,
argument types, keywords, target flags) and answers later calls with it. That is what the
template would compute again: the body's IR, its type map and call types are kept in
``template._inline_overloads[args]`` by the first call (as numba itself keeps them), and the
inliner copies that IR at each call site before changing it (``InlineWorker.inline_ir``),
so one typing serves every site. Only the ``inline="always"`` case is cached; numba's own
path is used for every other overload, and wherever its internals are not the ones this
was written against (the patch then does nothing).
"""
from __future__ import annotations

_CACHE_ATTRIBUTE = "_rtfgu_inline_signatures"


def cache_inline_typing() -> bool:
    """Install the cache on numba's overload template; True when installed (or already
    installed), False where numba's template does not have the expected shape."""
    try:
        from numba.core import targetconfig
        from numba.core.typing.templates import _OverloadFunctionTemplate
    except ImportError:
        return False
    generic = _OverloadFunctionTemplate.generic
    if getattr(generic, "_rtfgu_cached", False):
        return True
    if not hasattr(_OverloadFunctionTemplate, "_get_impl"):
        return False

    def cached_generic(self, args, kws):
        inline = getattr(self, "_inline", None)
        if inline is None or not inline.is_always_inline:
            return generic(self, args, kws)
        cache = self.__class__.__dict__.get(_CACHE_ATTRIBUTE)
        if cache is None:
            cache = {}
            setattr(self.__class__, _CACHE_ATTRIBUTE, cache)
        try:
            key = (self.context, tuple(args), tuple(sorted(kws.items())),
                   targetconfig.ConfigStack.top_or_none())
            hash(key)
        except TypeError:   # an unhashable argument type: type it as numba would
            return generic(self, args, kws)
        if key in cache:
            sig = cache[key]
            # The kept typing must still be there for the inliner (typed_passes.InlineOverloads).
            if sig is None or sig.args in self._inline_overloads:
                return sig
        sig = generic(self, args, kws)
        cache[key] = sig
        return sig

    cached_generic._rtfgu_cached = True
    cached_generic.numba_generic = generic   # numba's own, for the tests to compare with
    cached_generic.__doc__ = generic.__doc__
    _OverloadFunctionTemplate.generic = cached_generic
    return True
