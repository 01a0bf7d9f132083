:- module(oro_http_pengines, []).
:- use_module(library(pengines)).
:- use_module(library(sandbox)).
:- use_module(library(settings)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(oro), []).

/** <module> Pengines: oro's questions for Prolog planners in other processes

With the HTTP side running (oro_http), a planner in another process
asks oro through SWI-Prolog's Pengines, in the default application
`pengine_sandbox`:

    ?- pengine_rpc('http://127.0.0.1:6970',
                   oro_find(myself, x, ["?x isAt kitchen_table"], L), []).

The predicates of this module are those a remote goal may call, under
SWI-Prolog's sandbox (library(sandbox)) besides its safe built-ins:
oro's questions and taxonomy, each the predicate of library(oro) of
the same name.  The changes (oro_add/2, oro_remove/2, oro_update/2,
oro_clear/2) raise a permission error unless the setting `changes` is
true (the server's option `http_changes(true)`, `--http-changes`).
*/

:- setting(changes, boolean, false,
           'Whether Pengines clients may change the store').

%   remote_predicate(?PI): the predicates a remote goal may call (each
%   defined below as the predicate of library(oro) of the same name).
%   They are not exported, so that a module loading this one keeps
%   library(oro)'s own: the application pengine_sandbox gets a clause
%   of its own for each, calling this module's (SANDBOX below).

remote_predicate(oro_check/2).
remote_predicate(oro_find/4).
remote_predicate(oro_find/5).
remote_predicate(oro_holds/4).
remote_predicate(oro_type/3).
remote_predicate(oro_subclass/3).
remote_predicate(oro_subproperty/3).
remote_predicate(oro_class/2).
remote_predicate(oro_individual/2).
remote_predicate(oro_superclasses/3).
remote_predicate(oro_direct_superclasses/3).
remote_predicate(oro_subclasses/3).
remote_predicate(oro_direct_subclasses/3).
remote_predicate(oro_instances/3).
remote_predicate(oro_direct_instances/3).
remote_predicate(oro_classes_of/3).
remote_predicate(oro_direct_classes_of/3).
remote_predicate(oro_exists/2).
remote_predicate(oro_label/3).
remote_predicate(oro_lookup/3).
remote_predicate(oro_sparql/3).
remote_predicate(oro_agents/1).
remote_predicate(oro_add/2).
remote_predicate(oro_remove/2).
remote_predicate(oro_update/2).
remote_predicate(oro_clear/2).

%!  oro_check(+Model, +Patterns) is semidet.
%!  oro_find(+Model, ?Var, +Patterns, -Values) is det.
%!  oro_find(+Model, +Var, +Patterns, +Filters, -Values) is det.
%!  oro_holds(+Model, ?S, ?P, ?O) is nondet.
%!  oro_type(+Model, ?X, ?Class) is nondet.
%!  oro_subclass(+Model, ?Sub, ?Super) is nondet.
%!  oro_subproperty(+Model, ?Sub, ?Super) is nondet.
%!  oro_class(+Model, ?Class) is nondet.
%!  oro_individual(+Model, ?X) is nondet.
%!  oro_superclasses(+Model, +Class, -Supers) is det.
%!  oro_direct_superclasses(+Model, +Class, -Supers) is det.
%!  oro_subclasses(+Model, +Class, -Subs) is det.
%!  oro_direct_subclasses(+Model, +Class, -Subs) is det.
%!  oro_instances(+Model, +Class, -Instances) is det.
%!  oro_direct_instances(+Model, +Class, -Instances) is det.
%!  oro_classes_of(+Model, +Individual, -Classes) is det.
%!  oro_direct_classes_of(+Model, +Individual, -Classes) is det.
%!  oro_exists(+Model, +Resource) is semidet.
%!  oro_label(+Model, +Resource, -Label) is det.
%!  oro_lookup(+Model, +Text, -Matches) is det.
%!  oro_sparql(+Model, +Text, -Result) is det.
%!  oro_agents(-Names) is det.
%
%   The predicates of library(oro) of the same name, for remote goals.

oro_check(M, Ps) :- oro:oro_check(M, Ps).
oro_find(M, V, Ps, L) :- oro:oro_find(M, V, Ps, L).
oro_find(M, V, Ps, Fs, L) :- oro:oro_find(M, V, Ps, Fs, L).
oro_holds(M, S, P, O) :- oro:oro_holds(M, S, P, O).
oro_type(M, X, C) :- oro:oro_type(M, X, C).
oro_subclass(M, A, B) :- oro:oro_subclass(M, A, B).
oro_subproperty(M, A, B) :- oro:oro_subproperty(M, A, B).
oro_class(M, C) :- oro:oro_class(M, C).
oro_individual(M, X) :- oro:oro_individual(M, X).
oro_superclasses(M, C, L) :- oro:oro_superclasses(M, C, L).
oro_direct_superclasses(M, C, L) :- oro:oro_direct_superclasses(M, C, L).
oro_subclasses(M, C, L) :- oro:oro_subclasses(M, C, L).
oro_direct_subclasses(M, C, L) :- oro:oro_direct_subclasses(M, C, L).
oro_instances(M, C, L) :- oro:oro_instances(M, C, L).
oro_direct_instances(M, C, L) :- oro:oro_direct_instances(M, C, L).
oro_classes_of(M, X, L) :- oro:oro_classes_of(M, X, L).
oro_direct_classes_of(M, X, L) :- oro:oro_direct_classes_of(M, X, L).
oro_exists(M, X) :- oro:oro_exists(M, X).
oro_label(M, X, L) :- oro:oro_label(M, X, L).
oro_lookup(M, T, L) :- oro:oro_lookup(M, T, L).
oro_sparql(M, T, R) :- oro:oro_sparql(M, T, R).
oro_agents(L) :- oro:oro_agents(L).

%!  oro_add(+Model, +Statements) is det.
%!  oro_remove(+Model, +Statements) is det.
%!  oro_update(+Model, +Statements) is det.
%!  oro_clear(+Model, +Patterns) is det.
%
%   The predicates of library(oro) of the same name, when the setting
%   `changes` is true.
%
%   @error permission_error(modify, oro_store, Model) otherwise.

oro_add(M, Ss) :- change(M), oro:oro_add(M, Ss).
oro_remove(M, Ss) :- change(M), oro:oro_remove(M, Ss).
oro_update(M, Ss) :- change(M), oro:oro_update(M, Ss).
oro_clear(M, Ps) :- change(M), oro:oro_clear(M, Ps).

change(Model) :-
    (   setting(changes, true)
    ->  true
    ;   permission_error(modify, oro_store, Model)
    ).

%   Every predicate above is safe for the sandbox: it runs no goal of
%   its caller, and a change checks the setting itself.  The
%   application pengine_sandbox imports them.

:- multifile sandbox:safe_primitive/1.

sandbox:safe_primitive(oro_http_pengines:oro_check(_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_find(_,_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_find(_,_,_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_holds(_,_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_type(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_subclass(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_subproperty(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_class(_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_individual(_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_superclasses(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_direct_superclasses(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_subclasses(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_direct_subclasses(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_instances(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_direct_instances(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_classes_of(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_direct_classes_of(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_exists(_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_label(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_lookup(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_sparql(_,_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_agents(_)).
sandbox:safe_primitive(oro_http_pengines:oro_add(_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_remove(_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_update(_,_)).
sandbox:safe_primitive(oro_http_pengines:oro_clear(_,_)).

%   SANDBOX: for each remote predicate, a clause of pengine_sandbox
%   calling this module's, made when this file is compiled (as the
%   source of pengine_sandbox:Name/Arity).

term_expansion(sandbox_clauses, Clauses) :-
    findall(pengine_sandbox:(Head :- oro_http_pengines:Head),
            ( remote_predicate(Name/Arity),
              functor(Head, Name, Arity)
            ),
            Clauses).

sandbox_clauses.
