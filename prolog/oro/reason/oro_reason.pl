:- module(oro_reason,
          [ oro_holds/4,                % +Model, ?S, ?P, ?O
            oro_holds_normal/4,         % +Model, ?S, ?P, ?O
            oro_holds_keyed/5,          % +Key, +Model, ?S, ?P, ?O
            oro_holds_bag/6,            % +Model, ?Template, ?S, ?P, ?O, -Bag
            oro_type/3,                 % +Model, ?X, ?Class
            oro_subclass/3,             % +Model, ?Sub, ?Super
            oro_subproperty/3,          % +Model, ?Sub, ?Super
            oro_class/2,                % +Model, ?Class
            oro_property/3,             % +Model, ?Property, ?Kind
            oro_individual/2,           % +Model, ?X
            oro_same_individual/3,      % +Model, +X, -Y
            oro_has_same_individuals/1, % +Model
            oro_functional_property/2,  % +Model, ?Property
            oro_transitive_property/2,  % +Model, ?Property
            oro_property_characteristic/3, % +Model, ?Property, ?Characteristic
            oro_disjoint_classes/3,     % +Model, ?Class1, ?Class2
            oro_disjoint_properties/3,  % +Model, ?Property1, ?Property2
            oro_class_definition/3,     % +Model, ?Class, ?Definition
            oro_property_chain/3,       % +Model, ?Property, ?Links
            oro_property_way/4,         % +Model, +Property, ?Implying, ?Dir
            oro_datatype_member/2,      % +Literal, +Filler
            oro_literal_match/2,        % +Pattern, +Literal
            oro_meta_namespace/1,       % +IRI
            oro_compile_schema/2,       % +Model, -Key
            oro_compiled_schema/2,      % +Model, -Key
            oro_shared_schema/2,        % +Model, -Key
            oro_with_shared_schema/3,   % +Model, -Key, :Goal
            oro_schema_pin/0,
            oro_schema_unpin/0,
            oro_schema_superclass/3,    % +Key, +Class, -Super
            oro_drop_schema/1,          % +Key
            oro_with_schemas/2,         % +ModelKeys, :Goal
            oro_pattern_dependencies/3, % +Model, +Triples, -Predicates
            oro_rdf_list/3              % +Model, +List, -Members
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(debug)).
:- use_module(library(error)).
:- use_module(library(oro/oro_store)).

:- meta_predicate
    oro_with_schemas(+, 0),
    oro_with_shared_schema(+, -, 0),
    pinned(0).
:- use_module(library(oro/oro_names)).

/** <module> Reasoning: the inference closure of a model

oro answers every question over the *inference closure* of a model:
what was asserted plus what RDFS, the common OWL property axioms and
the OWL 2 RL class rules entail.  The mechanism is query-time
reasoning over small, precomputed schema closures:

  - The *schema* of a model (class and property hierarchies,
    owl:equivalentClass/Property, owl:inverseOf, symmetric, transitive
    and functional properties, domains, ranges, owl:sameAs, class
    expressions and property chains) is compiled into closure tables,
    once per schema change, and cached under a key.  A schema change
    (in any model or the ontology layer) bumps oro_store's generation
    counter; the next reader recompiles.  The tables replaced are freed
    once no thread reads shared tables (in a pinned region, see
    oro_with_shared_schema/3).
  - Instance triples are never materialised.  oro_holds/4 derives
    them when asked: a triple `S P O` holds if an asserted triple
    `S Q O` (or `O Q S`) implies it through the precomputed *ways* of
    P (sub-properties, equivalent and inverse properties, symmetry),
    or through the transitive closure of a transitive property that
    implies P.  Types come from asserted types, the class hierarchy,
    domains and ranges.  owl:sameAs individuals share everything.

## OWL 2 RL class expressions

Class expressions are read from the schema (restrictions are blank
nodes: their owl:onProperty, owl:hasValue, owl:someValuesFrom,
owl:allValuesFrom, and the RDF lists of owl:intersectionOf,
owl:unionOf, owl:oneOf and owl:propertyChainAxiom) and compiled to
tables (see oro_class_definition/3).  The rules of the OWL 2 RL
profile (W3C OWL 2 Profiles, section 4.3) that apply to them:

  | rule              | meaning                                       | where                  |
  |-------------------|-----------------------------------------------|------------------------|
  | cls-int2, scm-int | an intersection is below each member          | class hierarchy        |
  | cls-uni, scm-uni  | each member is below a union                  | class hierarchy        |
  | cls-int1          | `x` in every member is in the intersection     | derived type           |
  | cls-hv1           | `x : (P value v)` gives `x P v`                | derived triple         |
  | cls-hv2           | `x P v` gives `x : (P value v)`                | derived type           |
  | cls-svf1, cls-svf2| `x P y`, `y : C` gives `x : (P some C)`        | derived type           |
  | cls-avf           | `x : (P only C)`, `x P y` gives `y : C`        | derived type           |
  | cls-oo            | the members of `oneOf` are instances           | derived type           |
  | prp-spo2          | a property chain implies its property          | derived triple         |

A someValuesFrom/allValuesFrom filler may be owl:Thing, a class, or a
datatype (an xsd datatype, rdfs:Literal, or an owl:onDatatype
restriction with min/max inclusive/exclusive facets).  Derived triples
(hasValue and chains) are *virtual edges* of their property: they
imply its super-properties, inverses and transitive closure, and its
domain and range, as asserted edges do.

Derivation is goal-directed.  Class expressions can be cyclic (a
class equivalent to `(p value v)`, whose hasValue edge needs the type
that needs the edge), so every nested derivation of a type, of the
instances of a class or of a chain carries the set of goals in
progress (its *ancestors*): a goal that is a variant of an ancestor
fails, as does any derivation nested more than 64 deep.  For ground
questions ("is x a C?", "does x p y hold?") this loses nothing (a
derivation that needs itself is not one); when instances are
enumerated, an instance found only through a cycle between the
enumerations of two classes may be missed.

The fast paths do not pay for any of this: a schema without class
expressions or chains has no entry or virtual-edge tables, and each
question costs one failing index probe more than before.

Measured by bench/bench_reasoner.pl (SWI-Prolog 9.0.4, AMD EPYC, 50k
asserted triples over the common-sense ontology, IRIs given): a bare
rdf/3 probe 0.5 us, a triple asserted in the model 0.7 us, `x isOn y`
2.6 us, `x isAt y` through isOn 4.5 us, an asserted type 2.6 us, an
inferred type (Cup under Tableware under Artifact) 3.8 us, a false type
4.3 us; recompiling the schema 3.3 ms, done only on the first question
after a schema change.  These are the figures of the reasoner without
the class expressions, to the noise of the machine.  Over the
OpenRobots ontology (oro.owl: 13 hasValue restrictions, intersections,
unions) with 10k bottles: an inferred type 3.1 us, a hasValue edge
(`bottle hasShape cylinderShape`) 4.5 us, all the types of one bottle
0.2 ms, the 10k instances of Artifact 15 ms.
*/

:- rdf_meta
    oro_holds(+, r, r, o),
    oro_type(+, r, r),
    oro_subclass(+, r, r),
    oro_subproperty(+, r, r),
    oro_class(+, r),
    oro_property(+, r, ?),
    oro_individual(+, r),
    oro_property_characteristic(+, r, ?),
    oro_disjoint_classes(+, r, r),
    oro_disjoint_properties(+, r, r),
    oro_class_definition(+, r, ?),
    oro_property_chain(+, r, ?),
    oro_property_way(+, r, r, ?),
    special_predicate(r),
    meta_class(r),
    bare_type(r, -),
    facet(r, -).

:- dynamic
    schema_key/3,                   % Model, Generation, Key
    s_class/2,                      % Key, Class
    s_sub/3,                        % Key, Sub, Super (reflexive, transitive)
    s_prop/3,                       % Key, Property, Kind
    s_subprop/3,                    % Key, Sub, Super (reflexive, transitive)
    s_way/4,                        % Key, P, Q, Dir: Q-edges imply P
    s_has_ways/2,                   % Key, P
    s_trans_way/4,                  % Key, P, T, Dir: T transitive
    s_transitive/2,                 % Key, P
    s_functional/2,                 % Key, P
    s_subj_implies/3,               % Key, Q, Class
    s_obj_implies/3,                % Key, Q, Class
    s_same/3,                       % Key, X, Members
    s_has_same/1,                   % Key
    s_char/3,                       % Key, P, Characteristic
    s_disjoint/3,                   % Key, C1, C2 (both ways)
    s_prop_disjoint/3,              % Key, P, Q (both ways)
    s_def/3,                        % Key, Class, Definition
    s_chain/3,                      % Key, P, Links
    s_hv_edge/4,                    % Key, Q, Restriction, Value
    s_virtual/2,                    % Key, Q: Q has virtual edges
    s_virtual_way/4,                % Key, P, Q, Dir: virtual Q-edges imply P
    s_entry/3,                      % Key, Class, Condition
    s_entry_class/2,                % Key, Class
    s_entry_sub/3,                  % Key, EntryClass, Super
    s_has_entries/1,                % Key
    s_implied/2.                    % Key, Class: typed by more than rdf:type

		 /*******************************
		 *            SCHEMA            *
		 *******************************/

%!  schema(+Model, -Key) is det.
%
%   Key identifies the up-to-date schema closure tables of Model,
%   compiling them if the schema changed since they were made.

schema(Model, Key) :-
    (   cached_schema(Model, Key0)
    ->  Key = Key0
    ;   oro_store_schema_pending
    ->  private_schema(Model, Key)
    ;   oro_schema_generation(Gen),
        with_mutex(oro_schema, compile_schema_once(Model, Gen, Key))
    ).

%   model_schema(+Name, -Model, -Key): Model is the model Name
%   designates (a model or an alias: `default`, the robot id), Key its
%   shared schema tables, as schema/2 gives them; to be called in a
%   pinned region (pinned/1).  The entry of the public predicates,
%   which take a name as their caller wrote it.  A name that has tables
%   for the current schema is a model (tables are compiled for models
%   only, and a reset, which removes models, bumps the generation): it
%   is not resolved again, so that the small questions (is x a C?) cost
%   no more than with the model.  Raises existence_error(agent, Name) if
%   there is no such model.

model_schema(Name, Model, Key) :-
    (   atom(Name),
        cached_schema(Name, Key0)
    ->  Model = Name,
        Key = Key0
    ;   oro_resolve_model(Name, Model),
        schema(Model, Key)
    ).

%   cached_schema(+Model, -Key): the tables schema/2 would give without
%   compiling: those given for this thread (oro_with_schemas/2), else
%   the shared ones of the current generation, unless this thread's
%   write changed the schema (its tables are its own).

cached_schema(Model, Key) :-
    (   nb_current(oro_schema_keys, Keys),
        memberchk(Model-Key0, Keys)
    ->  Key = Key0
    ;   \+ oro_store_schema_pending,
        oro_schema_generation(Gen),
        schema_key(Model, Gen, Key)
    ).

%   The tables are kept for Gen only if no schema change started while
%   they were compiled (oro_store bumps the generation before a schema
%   change becomes visible and again once it is committed or rolled
%   back), so a cached key never holds a schema older or newer than its
%   generation.

compile_schema_once(Model, Gen, Key) :-
    (   schema_key(Model, Gen, Key0)
    ->  Key = Key0
    ;   flag(oro_schema_key, Key, Key+1),
        compile_schema(Model, Key),
        oro_schema_generation(Gen1),
        (   Gen1 == Gen
        ->  forall(retract(schema_key(Model, _, Old)),
                   drop_schema(Old)),
            assertz(schema_key(Model, Gen, Key)),
            debug(oro(reason), 'Schema of ~q compiled as ~q (generation ~q)',
                  [Model, Key, Gen])
        ;   drop_schema(Key)
        )
    ).

%   private_schema(+Model, -Key): the schema tables of Model for a
%   thread whose write has changed the schema (oro_store_schema_pending/0).
%   The generation is already bumped, but other threads do not see the
%   change yet: tables they compile for that generation lack it, and
%   tables this thread compiles must not reach them (the write may
%   still be rolled back).  So they are compiled for this thread alone,
%   once a generation, and kept in its global variable
%   oro_private_schemas (Model-Gen-Key), one a model; this thread
%   drops the older ones, and all of them when it ends.

private_schema(Model, Key) :-
    oro_schema_generation(Gen),
    (   nb_current(oro_private_schemas, Private)
    ->  true
    ;   Private = [],
        thread_at_exit(drop_private_schemas)
    ),
    (   memberchk(Model-Gen-Key0, Private)
    ->  Key = Key0
    ;   oro_compile_schema(Model, Key),
        (   selectchk(Model-_-Old, Private, Rest)
        ->  retract_schema(Old)
        ;   Rest = Private
        ),
        nb_setval(oro_private_schemas, [Model-Gen-Key|Rest])
    ).

drop_private_schemas :-
    (   nb_current(oro_private_schemas, Private)
    ->  forall(member(_-_-Key, Private), retract_schema(Key))
    ;   true
    ).

%!  oro_compile_schema(+Model, -Key) is det.
%
%   Compile the schema of Model as the calling thread sees the store
%   now (in a snapshot, for instance) into fresh tables identified by
%   Key, outside the shared cache.  Use it with oro_with_schemas/2 and
%   release it with oro_drop_schema/1.  The event watcher uses this to
%   evaluate each change with the schema of that very change.

oro_compile_schema(Model, Key) :-
    must_be(atom, Model),
    flag(oro_schema_key, Key, Key+1),
    compile_schema(Model, Key).

%!  oro_compiled_schema(+Model, -Key) is semidet.
%
%   Key identifies the shared schema tables of Model for the current
%   schema generation, if a thread has compiled them already; fails
%   otherwise.  Unlike the other predicates of this module it never
%   compiles: for the events monitor, which must stay cheap and does
%   something safe instead.  A caller that reads the tables with Key
%   must be in a pinned region, entered before this call (see
%   oro_schema_pin/0).

oro_compiled_schema(Model, Key) :-
    must_be(atom, Model),
    oro_schema_generation(Gen),
    schema_key(Model, Gen, Key),
    !.

%!  oro_shared_schema(+Model, -Key) is det.
%
%   Key identifies the shared schema tables of Model for the current
%   schema generation, compiled now if no thread has yet (the tables
%   every query of Model uses).  Once a schema change has replaced
%   them, they are freed as soon as no thread is in a pinned region
%   (see oro_with_shared_schema/3): a caller that reads them with Key
%   must do so in one.

oro_shared_schema(Model, Key) :-
    must_be(atom, Model),
    schema(Model, Key).

%!  oro_with_shared_schema(+Model, -Key, :Goal) is nondet.
%
%   Call Goal with Key, the schema tables of Model as
%   oro_shared_schema/2 gives them, in a pinned region: the tables of
%   Key are not freed while Goal runs or has choice points left, even
%   if a schema change replaces them meanwhile.

oro_with_shared_schema(Model, Key, Goal) :-
    must_be(atom, Model),
    pinned(with_shared_schema(Model, Key, Goal)).

with_shared_schema(Model, Key, Goal) :-
    schema(Model, Key),
    call(Goal).

%!  oro_schema_superclass(+Key, +Class, -Super) is nondet.
%
%   Super is a (reflexive, transitive) super-class of the atom Class
%   in the schema tables Key, as oro_subclass/3 enumerates them.

oro_schema_superclass(Key, Class, Super) :-
    must_be(atom, Class),
    sub_class_of(Key, Class, Super).

%!  oro_drop_schema(+Key) is det.
%
%   Release tables made by oro_compile_schema/2.

oro_drop_schema(Key) :-
    must_be(integer, Key),
    retract_schema(Key).

%!  oro_with_schemas(+ModelKeys, :Goal) is semidet.
%
%   Run Goal (once) with the schema tables of each Model-Key pair of
%   ModelKeys instead of the shared cache, in this thread.

oro_with_schemas(ModelKeys, Goal) :-
    must_be(list, ModelKeys),
    (   nb_current(oro_schema_keys, Old)
    ->  true
    ;   Old = []
    ),
    setup_call_cleanup(
        b_setval(oro_schema_keys, ModelKeys),
        once(Goal),
        b_setval(oro_schema_keys, Old)).


		 /*******************************
		 *        PINNED READERS        *
		 *******************************/

%   The shared tables of a key replaced by a schema change (retired)
%   must outlive every reader that was handed the key, in any thread.
%   A reader of shared tables runs in a *pinned region* (pinned/1):
%   the flag oro_schema_readers counts the regions entered and not yet
%   left, in all threads, and a key retired while it is not 0 waits in
%   retired/1 until the last reader leaves, which frees it.  The count and retired/1 are guarded by the
%   mutex oro_schema_pin.
%
%   Why no reader sees its tables vanish: a key is retired
%   (drop_schema/1) only after it has been taken out of schema_key/3
%   (or was never put there), so no thread is handed it afterwards;
%   and a reader counts itself in (pin/0) *before* schema/2 reads
%   schema_key/3.  The retirement reads the count under the mutex, and
%   so is ordered with each pin: a reader that pinned first is counted,
%   and the key waits until it unpins; a reader that pins afterwards
%   reads schema_key/3 after the key was taken out, and cannot get it.
%   Keys private to a thread (private_schema/2, oro_compile_schema/2,
%   oro_with_schemas/2) are freed by their owner and need no pin.
%
%   Under readers that overlap without end, retired tables wait for a
%   moment with no reader; a reader that leaves choice points open
%   holds its pin until they are cut.

:- dynamic retired/1.

%   pinned(:Goal): Goal, possibly nondeterministic, in a pinned region,
%   held while Goal runs or has choice points.

pinned(Goal) :-
    setup_call_cleanup(pin, Goal, unpin).

%!  oro_schema_pin is det.
%!  oro_schema_unpin is det.
%
%   Enter and leave a pinned region (see oro_with_shared_schema/3) that
%   is not a goal: the events monitor holds one from the moment it
%   reads the shared tables' key until the end of the commit whose
%   triples it classifies with it.  Each pin must be matched by one
%   unpin, and both must run with signals blocked (sig_atomic/1), so
%   that the mutex they take is never left locked.

oro_schema_pin :-
    pin.

oro_schema_unpin :-
    unpin.

%   pin and unpin run in the setup and cleanup of setup_call_cleanup/3,
%   where signals wait, so mutex_lock/1 and mutex_unlock/1 are paired.
%   (Not flag/3, which meta-calls update_flag/3 under a global mutex,
%   nor with_mutex/2 of a conjunction, which is compiled at each call:
%   this is on the path of every query.)  The last reader takes the
%   retired keys, and frees their tables after unlocking.

pin :-
    mutex_lock(oro_schema_pin),
    get_flag(oro_schema_readers, N0),
    N is N0 + 1,
    set_flag(oro_schema_readers, N),
    mutex_unlock(oro_schema_pin).

unpin :-
    mutex_lock(oro_schema_pin),
    get_flag(oro_schema_readers, N0),
    N is N0 - 1,
    set_flag(oro_schema_readers, N),
    (   N =:= 0,
        retired(_)
    ->  findall(Key, retract(retired(Key)), Keys)
    ;   Keys = []
    ),
    mutex_unlock(oro_schema_pin),
    maplist(retract_schema, Keys).

%   drop_schema(+Key): retire the shared tables Key, out of
%   schema_key/3: freed now if no thread is in a pinned region, else
%   when the last one leaves.  Under with_mutex/2: it is called while a
%   query compiles the tables, where a signal (the query's time limit)
%   may come.

drop_schema(Key) :-
    with_mutex(oro_schema_pin, retire(Key, Free)),
    (   Free == true
    ->  retract_schema(Key)
    ;   true
    ).

retire(Key, Free) :-
    get_flag(oro_schema_readers, N),
    (   N =:= 0
    ->  Free = true
    ;   assertz(retired(Key)),
        Free = false
    ).

retract_schema(Key) :-
    retractall(s_class(Key, _)),
    retractall(s_sub(Key, _, _)),
    retractall(s_prop(Key, _, _)),
    retractall(s_subprop(Key, _, _)),
    retractall(s_way(Key, _, _, _)),
    retractall(s_has_ways(Key, _)),
    retractall(s_trans_way(Key, _, _, _)),
    retractall(s_transitive(Key, _)),
    retractall(s_functional(Key, _)),
    retractall(s_subj_implies(Key, _, _)),
    retractall(s_obj_implies(Key, _, _)),
    retractall(s_same(Key, _, _)),
    retractall(s_has_same(Key)),
    retractall(s_char(Key, _, _)),
    retractall(s_disjoint(Key, _, _)),
    retractall(s_prop_disjoint(Key, _, _)),
    retractall(s_def(Key, _, _)),
    retractall(s_chain(Key, _, _)),
    retractall(s_hv_edge(Key, _, _, _)),
    retractall(s_virtual(Key, _)),
    retractall(s_virtual_way(Key, _, _, _)),
    retractall(s_entry(Key, _, _)),
    retractall(s_entry_class(Key, _)),
    retractall(s_entry_sub(Key, _, _)),
    retractall(s_has_entries(Key)),
    retractall(s_implied(Key, _)).

compile_schema(Model, Key) :-
    findall(C-Def, class_definition(Model, C, Def), Defs0),
    sort(Defs0, Defs),
    compile_classes(Model, Key, Defs),
    compile_properties(Model, Key),
    compile_implications(Model, Key),
    compile_same_as(Model, Key),
    compile_axioms(Model, Key),
    compile_rl(Model, Key, Defs),
    compile_implied(Key).

schema_pairs(Model, P, Pairs) :-
    findall(S-O, oro_asserted(Model, S, P, O), Pairs0),
    sort(Pairs0, Pairs).

%   Classes and their reflexive-transitive super classes.  An
%   intersection is below each of its members and each member of a
%   union below the union.

compile_classes(Model, Key, Defs) :-
    rdf_equal(rdfs:subClassOf, SubClassOf),
    rdf_equal(owl:equivalentClass, Equivalent),
    schema_pairs(Model, SubClassOf, Subs),
    schema_pairs(Model, Equivalent, Eqs),
    findall(C, declared_class(Model, C), Declared),
    findall(C, ( member(D-Def, Defs),
                 (   C = D
                 ;   definition_class(Def, C)
                 )
               ), Defined),
    pairs_keys_values(Subs, SubKeys, SubValues),
    pairs_keys_values(Eqs, EqKeys, EqValues),
    append([Declared, Defined, SubKeys, SubValues, EqKeys, EqValues],
           Classes0),
    rdf_equal(owl:'Thing', Thing),
    sort([Thing|Classes0], Classes),
    findall(A-B, ( member(A-B, Subs)
                 ; member(A-B, Eqs)
                 ; member(B-A, Eqs)
                 ; member(A-intersection(Ms), Defs),
                   member(B, Ms)
                 ; member(B-union(Ms), Defs),
                   member(A, Ms)
                 ), Edges0),
    sort(Edges0, Edges),
    edges_graph(Classes, Edges, Graph),
    forall(member(C, Classes),
           ( assertz(s_class(Key, C)),
             reachable(Graph, C, Supers),
             forall(member(D, [C, Thing|Supers]),
                    assert_once(s_sub(Key, C, D)))
           )).

%   definition_class(+Definition, -Class): a class a definition names.

definition_class(intersection(Ms), C) :-
    member(C, Ms).
definition_class(union(Ms), C) :-
    member(C, Ms).
definition_class(some_values(_, class(C)), C).
definition_class(all_values(_, class(C)), C).

declared_class(Model, C) :-
    rdf_equal(rdf:type, Type),
    (   rdf_equal(owl:'Class', Meta)
    ;   rdf_equal(rdfs:'Class', Meta)
    ;   rdf_equal(owl:'Restriction', Meta)
    ),
    oro_asserted(Model, C, Type, Meta).
declared_class(Model, C) :-
    (   rdf_equal(rdfs:domain, P)
    ;   rdf_equal(rdfs:range, P)
    ),
    oro_asserted(Model, _, P, C),
    atom(C),
    \+ datatype(C).
declared_class(Model, C) :-
    (   rdf_equal(owl:disjointWith, P)
    ;   rdf_equal(owl:complementOf, P)
    ),
    (   oro_asserted(Model, C, P, _)
    ;   oro_asserted(Model, _, P, C)
    ).

datatype(C) :-
    rdf_equal(rdfs:'Literal', C),
    !.
datatype(C) :-
    rdf_equal(xsd:'', XSD),
    sub_atom(C, 0, _, _, XSD).

assert_once(Fact) :-
    (   call(Fact)
    ->  true
    ;   assertz(Fact)
    ).

%!  edges_graph(+Nodes, +Edges, -Graph) is det.
%!  reachable(+Graph, +Node, -Reached) is det.
%
%   Graph is an assoc from each node to its direct successors; Reached
%   is the ordered set of nodes reachable from Node in one or more steps
%   (Node itself only through a cycle, which equivalence creates).

edges_graph(Nodes, Edges, Graph) :-
    findall(N-[], member(N, Nodes), Empty),
    list_to_assoc(Empty, Graph0),
    foldl(add_edge, Edges, Graph0, Graph).

add_edge(A-B, G0, G) :-
    (   get_assoc(A, G0, Succ)
    ->  put_assoc(A, G0, [B|Succ], G)
    ;   put_assoc(A, G0, [B], G)
    ).

reachable(Graph, Node, Reached) :-
    successors(Graph, Node, Start),
    closure(Start, Graph, [], Reached).

closure([], _, Seen, Reached) :-
    sort(Seen, Reached).
closure([H|T], Graph, Seen, Reached) :-
    (   memberchk(H, Seen)
    ->  closure(T, Graph, Seen, Reached)
    ;   successors(Graph, H, Next),
        append(Next, T, Queue),
        closure(Queue, Graph, [H|Seen], Reached)
    ).

successors(Graph, Node, Succ) :-
    (   get_assoc(Node, Graph, Succ0)
    ->  Succ = Succ0
    ;   Succ = []
    ).

%   Properties: hierarchy, characteristics and the ways asserted edges
%   imply each property.

compile_properties(Model, Key) :-
    rdf_equal(rdfs:subPropertyOf, SubPropertyOf),
    rdf_equal(owl:equivalentProperty, Equivalent),
    rdf_equal(owl:inverseOf, InverseOf),
    schema_pairs(Model, SubPropertyOf, Subs),
    schema_pairs(Model, Equivalent, Eqs),
    schema_pairs(Model, InverseOf, Invs),
    findall(P-Kind, declared_property(Model, P, Kind), Declared),
    findall(P, ( member(P-_, Declared)
               ; member(P-_, Subs) ; member(_-P, Subs)
               ; member(P-_, Eqs) ; member(_-P, Eqs)
               ; member(P-_, Invs) ; member(_-P, Invs)
               ), Props0),
    sort(Props0, Props),
    findall(A-B, ( member(A-B, Subs)
                 ; member(A-B, Eqs)
                 ; member(B-A, Eqs)
                 ), SubEdges0),
    sort(SubEdges0, SubEdges),
    edges_graph(Props, SubEdges, SubGraph),
    forall(member(P, Props),
           ( reachable(SubGraph, P, Supers),
             forall(member(Q, [P|Supers]),
                    assert_once(s_subprop(Key, P, Q)))
           )),
    forall(member(P, Props),
           ( property_kind(Model, Key, P, Declared, Invs, Kind),
             assertz(s_prop(Key, P, Kind))
           )),
    forall(characteristic(Model, P, transitive),
           assert_once(s_transitive(Key, P))),
    forall(characteristic(Model, P, functional),
           assert_once(s_functional(Key, P))),
    findall(P, characteristic(Model, P, symmetric), Symmetric0),
    sort(Symmetric0, Symmetric),
    % ways: from (P, fwd), walk to sub-properties, inverses, symmetry
    findall(Super-Sub, member(Sub-Super, SubEdges), DownEdges),
    edges_graph(Props, DownEdges, DownGraph),
    findall(A-B, ( member(A-B, Invs) ; member(B-A, Invs) ), InvEdges),
    edges_graph(Props, InvEdges, InvGraph),
    forall(member(P, Props),
           ( ways(P, DownGraph, InvGraph, Symmetric, Ways),
             assertz(s_has_ways(Key, P)),
             forall(member(Q-Dir, Ways),
                    ( assertz(s_way(Key, P, Q, Dir)),
                      (   s_transitive(Key, Q)
                      ->  assertz(s_trans_way(Key, P, Q, Dir))
                      ;   true
                      )
                    ))
           )).

declared_property(Model, P, Kind) :-
    rdf_equal(rdf:type, Type),
    property_class(Class, Kind),
    oro_asserted(Model, P, Type, Class).
declared_property(Model, P, other) :-
    (   rdf_equal(rdfs:domain, D)
    ;   rdf_equal(rdfs:range, D)
    ),
    oro_asserted(Model, P, D, _).

:- rdf_meta property_class(r, -), characteristic_class(r, -).

property_class(owl:'ObjectProperty', object).
property_class(owl:'DatatypeProperty', datatype).
property_class(owl:'AnnotationProperty', annotation).
property_class(rdf:'Property', other).
property_class(owl:'TransitiveProperty', object).
property_class(owl:'SymmetricProperty', object).
property_class(owl:'FunctionalProperty', other).
property_class(owl:'InverseFunctionalProperty', object).
property_class(owl:'AsymmetricProperty', object).
property_class(owl:'IrreflexiveProperty', object).
property_class(owl:'ReflexiveProperty', object).

%   property_kind(+Model, +Key, +P, +Declared, +Inverses, -Kind): the
%   declared kind, else what the schema says: an inverse is an object
%   property, a sub-property has the kind of its super-properties, a
%   datatype range makes a datatype property and a class range an
%   object property.  What remains `other` is typed by its values at
%   query time (used_kind/4).

property_kind(Model, Key, P, Declared, Invs, Kind) :-
    (   declared_kind(P, Declared, Kind0)
    ->  Kind = Kind0
    ;   (   memberchk(P-_, Invs)
        ;   memberchk(_-P, Invs)
        )
    ->  Kind = object
    ;   s_subprop(Key, P, Q),
        Q \== P,
        declared_kind(Q, Declared, Kind0)
    ->  Kind = Kind0
    ;   rdf_equal(rdfs:range, Range),
        oro_asserted(Model, P, Range, R),
        atom(R)
    ->  (   datatype(R)
        ->  Kind = datatype
        ;   Kind = object
        )
    ;   Kind = other
    ).

declared_kind(P, Declared, Kind) :-
    (   memberchk(P-object, Declared)
    ->  Kind = object
    ;   memberchk(P-datatype, Declared)
    ->  Kind = datatype
    ;   memberchk(P-annotation, Declared)
    ->  Kind = annotation
    ).

characteristic(Model, P, Char) :-
    rdf_equal(rdf:type, Type),
    characteristic_class(Class, Char),
    oro_asserted(Model, P, Type, Class).

characteristic_class(owl:'TransitiveProperty', transitive).
characteristic_class(owl:'SymmetricProperty', symmetric).
characteristic_class(owl:'FunctionalProperty', functional).
characteristic_class(owl:'InverseFunctionalProperty', inverse_functional).
characteristic_class(owl:'AsymmetricProperty', asymmetric).
characteristic_class(owl:'IrreflexiveProperty', irreflexive).
characteristic_class(owl:'ReflexiveProperty', reflexive).

ways(P, DownGraph, InvGraph, Symmetric, Ways) :-
    way_closure([P-fwd], DownGraph, InvGraph, Symmetric, [], Ways).

way_closure([], _, _, _, Seen, Ways) :-
    sort(Seen, Ways).
way_closure([Q-D|T], Down, Inv, Sym, Seen, Ways) :-
    (   memberchk(Q-D, Seen)
    ->  way_closure(T, Down, Inv, Sym, Seen, Ways)
    ;   flip(D, F),
        successors(Down, Q, Subs),
        successors(Inv, Q, Invs),
        findall(S-D, member(S, Subs), Next1),
        findall(I-F, member(I, Invs), Next2),
        (   memberchk(Q, Sym)
        ->  Next3 = [Q-F]
        ;   Next3 = []
        ),
        append([Next1, Next2, Next3, T], Queue),
        way_closure(Queue, Down, Inv, Sym, [Q-D|Seen], Ways)
    ).

flip(fwd, bwd).
flip(bwd, fwd).

%   Domains and ranges: which asserted edges imply which types.

compile_implications(Model, Key) :-
    rdf_equal(rdfs:domain, Domain),
    rdf_equal(rdfs:range, Range),
    schema_pairs(Model, Domain, Domains),
    schema_pairs(Model, Range, Ranges),
    forall(( member(P-C, Domains),
             atom(C),
             way(Key, P, Q, Dir),
             sub_class_of(Key, C, Super)
           ),
           (   Dir == fwd
           ->  assert_once(s_subj_implies(Key, Q, Super))
           ;   assert_once(s_obj_implies(Key, Q, Super))
           )),
    forall(( member(P-C, Ranges),
             atom(C),
             \+ datatype(C),
             way(Key, P, Q, Dir),
             sub_class_of(Key, C, Super)
           ),
           (   Dir == fwd
           ->  assert_once(s_obj_implies(Key, Q, Super))
           ;   assert_once(s_subj_implies(Key, Q, Super))
           )).

%   s_implied(Key, C): C has instances other than those of its asserted
%   sub-classes, implied by a domain, a range or an entry class.  A
%   type check against any other class looks at the asserted types
%   alone.

compile_implied(Key) :-
    forall(( s_subj_implies(Key, _, C)
           ; s_obj_implies(Key, _, C)
           ; s_entry_sub(Key, _, C)
           ),
           assert_once(s_implied(Key, C))).

%   owl:sameAs equivalence classes.

compile_same_as(Model, Key) :-
    rdf_equal(owl:sameAs, SameAs),
    schema_pairs(Model, SameAs, Pairs),
    (   Pairs == []
    ->  true
    ;   assertz(s_has_same(Key)),
        findall(A-B, ( member(A-B, Pairs) ; member(B-A, Pairs) ), Edges),
        pairs_keys(Edges, Nodes0),
        sort(Nodes0, Nodes),
        edges_graph(Nodes, Edges, Graph),
        forall(member(N, Nodes),
               ( reachable(Graph, N, Reached),
                 ord_union([N], Reached, Members),
                 assertz(s_same(Key, N, Members))
               ))
    ).

%   The axioms the consistency checks need: property characteristics,
%   disjoint classes (owl:disjointWith, owl:complementOf,
%   owl:AllDisjointClasses) and disjoint properties
%   (owl:propertyDisjointWith, owl:AllDisjointProperties), both ways.

compile_axioms(Model, Key) :-
    forall(( characteristic(Model, P, Char),
             Char \== transitive,
             Char \== symmetric
           ),
           assert_once(s_char(Key, P, Char))),
    forall(declared_disjoint(Model, A, B),
           ( assert_once(s_disjoint(Key, A, B)),
             assert_once(s_disjoint(Key, B, A))
           )),
    forall(declared_disjoint_properties(Model, P, Q),
           ( assert_once(s_prop_disjoint(Key, P, Q)),
             assert_once(s_prop_disjoint(Key, Q, P))
           )).

declared_disjoint(Model, A, B) :-
    (   rdf_equal(owl:disjointWith, P)
    ;   rdf_equal(owl:complementOf, P)
    ),
    oro_asserted(Model, A, P, B).
declared_disjoint(Model, A, B) :-
    rdf_equal(owl:'AllDisjointClasses', All),
    all_members(Model, All, Classes),
    select(A, Classes, Others),
    member(B, Others).

declared_disjoint_properties(Model, P, Q) :-
    rdf_equal(owl:propertyDisjointWith, DP),
    oro_asserted(Model, P, DP, Q).
declared_disjoint_properties(Model, P, Q) :-
    rdf_equal(owl:'AllDisjointProperties', All),
    all_members(Model, All, Props),
    select(P, Props, Others),
    member(Q, Others).

all_members(Model, Class, Members) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:members, MembersP),
    oro_asserted(Model, Axiom, Type, Class),
    oro_asserted(Model, Axiom, MembersP, List),
    oro_rdf_list(Model, List, Members).

%!  oro_rdf_list(+Model, +List, -Members) is semidet.
%
%   Members are the elements of the well-formed RDF list List asserted
%   in Model (at most 10,000); fails on a malformed or cyclic list.

oro_rdf_list(Model, List, Members) :-
    rdf_equal(rdf:nil, Nil),
    rdf_equal(rdf:first, First),
    rdf_equal(rdf:rest, Rest),
    list_members(Model, List, Nil, First, Rest, Members, 10000).

list_members(_, Nil, Nil, _, _, [], _) :-
    !.
list_members(Model, Cell, Nil, First, Rest, [H|T], Budget) :-
    Budget > 0,
    oro_asserted(Model, Cell, First, H),
    oro_asserted(Model, Cell, Rest, Next),
    !,
    Budget1 is Budget - 1,
    list_members(Model, Next, Nil, First, Rest, T, Budget1).

		 /*******************************
		 *       CLASS EXPRESSIONS      *
		 *******************************/

%   class_definition(+Model, -Class, -Definition): a class expression
%   of the schema.

class_definition(Model, R, Def) :-
    rdf_equal(owl:onProperty, OnProperty),
    oro_asserted(Model, R, OnProperty, P),
    atom(P),
    \+ rdf_is_bnode(P),
    restriction(Model, R, P, Def).
class_definition(Model, C, Def) :-
    list_constructor(P, Functor),
    oro_asserted(Model, C, P, List),
    oro_rdf_list(Model, List, Members),
    Def =.. [Functor, Members].

:- rdf_meta
    list_constructor(r, -).

list_constructor(owl:intersectionOf, intersection).
list_constructor(owl:unionOf, union).
list_constructor(owl:oneOf, one_of).

restriction(Model, R, P, has_value(P, V)) :-
    rdf_equal(owl:hasValue, HasValue),
    oro_asserted(Model, R, HasValue, V).
restriction(Model, R, P, some_values(P, Filler)) :-
    rdf_equal(owl:someValuesFrom, Some),
    oro_asserted(Model, R, Some, F),
    filler(Model, F, Filler).
restriction(Model, R, P, all_values(P, Filler)) :-
    rdf_equal(owl:allValuesFrom, All),
    oro_asserted(Model, R, All, F),
    filler(Model, F, Filler).

%   filler(+Model, +Class, -Filler): `thing`, class(C) or
%   datatype(Datatype, Facets).

filler(Model, F, Filler) :-
    (   rdf_equal(F, owl:'Thing')
    ->  Filler = thing
    ;   atom(F),
        datatype(F)
    ->  Filler = datatype(F, [])
    ;   rdf_equal(owl:onDatatype, OnDatatype),
        oro_asserted(Model, F, OnDatatype, DT)
    ->  datatype_facets(Model, F, Facets),
        Filler = datatype(DT, Facets)
    ;   rdf_equal(rdf:type, Type),
        rdf_equal(rdfs:'Datatype', Datatype),
        oro_asserted(Model, F, Type, Datatype)
    ->  Filler = datatype(F, [unsupported])
    ;   Filler = class(F)
    ).

%   The facets of a datatype restriction: Name-Literal pairs of the
%   four range facets; any other facet is `unsupported` (it never
%   matches rather than matching too much).

datatype_facets(Model, F, Facets) :-
    rdf_equal(owl:withRestrictions, With),
    (   oro_asserted(Model, F, With, List),
        oro_rdf_list(Model, List, Items)
    ->  findall(Facet, ( member(Item, Items),
                         oro_asserted(Model, Item, P, V),
                         (   facet(P, Name)
                         ->  Facet = Name-V
                         ;   Facet = unsupported
                         )
                       ), Facets)
    ;   Facets = [unsupported]
    ).

facet(xsd:minInclusive, min_inclusive).
facet(xsd:maxInclusive, max_inclusive).
facet(xsd:minExclusive, min_exclusive).
facet(xsd:maxExclusive, max_exclusive).

chain_axiom(Model, P, Links) :-
    rdf_equal(owl:propertyChainAxiom, Chain),
    oro_asserted(Model, P, Chain, List),
    oro_rdf_list(Model, List, Members),
    Members \== [],
    maplist(chain_link(Model), Members, Links).

chain_link(Model, L, Link) :-
    (   rdf_is_bnode(L)
    ->  rdf_equal(owl:inverseOf, InverseOf),
        oro_asserted(Model, L, InverseOf, Q),
        atom(Q),
        Link = inverse(Q)
    ;   atom(L),
        Link = L
    ).

%   compile_rl(+Model, +Key, +Defs): the tables of class expressions
%   and chains.
%
%     - s_hv_edge(Key, Q, R, V): an instance of R has a virtual Q-edge
%       to V (cls-hv1); s_chain(Key, Q, Links): chains imply Q.
%     - s_virtual_way(Key, P, Q, Dir): virtual Q-edges imply P.
%     - s_entry(Key, D, Condition): a condition on an individual that
%       makes it an instance of D (cls-hv2, cls-svf1/2, cls-int1,
%       cls-oo, cls-avf, and domains and ranges of virtual edges);
%       s_entry_sub(Key, D, C): D is an entry class below C.
%
%   An entry is compiled only if its class matters: it is named, or is
%   used by another class expression or a disjointness axiom, or has
%   such a super-class.  `Bottle rdfs:subClassOf (hasShape value
%   cylinderShape)` makes every bottle have that shape, but does not
%   make everything of that shape an instance of the anonymous class.

compile_rl(Model, Key, Defs) :-
    forall(member(C-Def, Defs), assertz(s_def(Key, C, Def))),
    forall(chain_axiom(Model, P, Links), assertz(s_chain(Key, P, Links))),
    forall(member(R-has_value(Q, V), Defs),
           assertz(s_hv_edge(Key, Q, R, V))),
    findall(Q, ( s_hv_edge(Key, Q, _, _) ; s_chain(Key, Q, _) ), Vs0),
    sort(Vs0, Virtuals),
    forall(member(Q, Virtuals),
           ( assertz(s_virtual(Key, Q)),
             forall(implied_by(Key, Q, P, Dir),
                    assert_once(s_virtual_way(Key, P, Q, Dir)))
           )),
    findall(D-Cond, entry_condition(Model, Key, Defs, D, Cond), Entries0),
    sort(Entries0, Entries),
    relevant_classes(Key, Defs, Relevant),
    forall(( member(D-Cond, Entries),
             useful_entry(Key, Relevant, D)
           ),
           ( assertz(s_entry(Key, D, Cond)),
             assert_once(s_entry_class(Key, D)),
             assert_once(s_has_entries(Key)),
             forall(( entry_super(Key, D, C),
                      \+ redundant_entry(Key, Cond, C)
                    ),
                    assert_once(s_entry_sub(Key, D, C)))
           )).

%   An instance of an intersection is an instance of each member: for a
%   class C above one of the members, the intersection's entry finds
%   nothing the member does not (`Book rdfs:subClassOf (Artifact and
%   ...)` need not be tried for the instances of Artifact).

redundant_entry(Key, all_of(Ms), C) :-
    member(M, Ms),
    s_sub(Key, M, C),
    !.

%   implied_by(+Key, +Q, -P, -Dir): Q-edges imply P.

implied_by(Key, Q, P, Dir) :-
    (   s_has_ways(Key, Q)
    ->  s_way(Key, P, Q, Dir)
    ;   s_way(Key, P, Q, Dir)
    ;   P = Q,
        Dir = fwd
    ).

entry_super(Key, D, C) :-
    rdf_equal(owl:'Thing', Thing),
    (   s_sub(Key, D, C)
    *-> C \== Thing
    ;   C = D
    ).

entry_condition(_, _, Defs, D, value(Q, V)) :-
    member(D-has_value(Q, V), Defs).
entry_condition(_, _, Defs, D, some(Q, F)) :-
    member(D-some_values(Q, F), Defs).
entry_condition(_, _, Defs, D, all_of(Ms)) :-
    member(D-intersection(Ms0), Defs),
    Ms0 \== [],
    map_list_to_pairs(member_selectivity(Defs), Ms0, Keyed),
    keysort(Keyed, Sorted),
    pairs_values(Sorted, Ms).

entry_condition(_, _, Defs, D, one_of(Xs)) :-
    member(D-one_of(Xs), Defs).
entry_condition(_, _, Defs, C, avf(Q, R)) :-
    member(R-all_values(Q, class(C)), Defs).
entry_condition(Model, Key, _, C, Cond) :-
    rdf_equal(rdfs:domain, Domain),
    s_virtual(Key, Q),
    implied_by(Key, Q, P, Dir),
    oro_asserted(Model, P, Domain, C),
    atom(C),
    (   Dir == fwd
    ->  Cond = vsubj(Q)
    ;   Cond = vobj(Q)
    ).
entry_condition(Model, Key, _, C, Cond) :-
    rdf_equal(rdfs:range, Range),
    s_virtual(Key, Q),
    implied_by(Key, Q, P, Dir),
    oro_asserted(Model, P, Range, C),
    atom(C),
    \+ datatype(C),
    (   Dir == fwd
    ->  Cond = vobj(Q)
    ;   Cond = vsubj(Q)
    ).

%   member_selectivity(+Defs, +Class, -Rank): the instances of an
%   intersection are enumerated from its first member: a hasValue or
%   oneOf member has few, a named class may have many.

member_selectivity(Defs, C, Rank) :-
    (   memberchk(C-Def, Defs)
    ->  definition_rank(Def, Rank)
    ;   Rank = 5
    ).

definition_rank(has_value(_, _), 1).
definition_rank(one_of(_), 1).
definition_rank(some_values(_, class(_)), 3).
definition_rank(intersection(_), 4).
definition_rank(some_values(_, _), 6).
definition_rank(union(_), 6).
definition_rank(all_values(_, _), 7).

relevant_classes(Key, Defs, Relevant) :-
    findall(C, ( member(_-Def, Defs),
                 (   Def = intersection(Ms),
                     member(C, Ms)
                 ;   Def = some_values(_, class(C))
                 )
               ; member(C-all_values(_, _), Defs)
               ; s_disjoint(Key, C, _)
               ), Relevant0),
    sort(Relevant0, Relevant).

useful_entry(Key, Relevant, D) :-
    rdf_equal(owl:'Thing', Thing),
    s_sub(Key, D, S),
    S \== Thing,
    (   \+ rdf_is_bnode(S)
    ->  true
    ;   ord_memberchk(S, Relevant)
    ),
    !.

		 /*******************************
		 *        SCHEMA ACCESS         *
		 *******************************/

%   sub_class_of(+Key, ?Sub, ?Super): reflexive; a class unknown to
%   the schema (only used as a type) is its own class under owl:Thing.

sub_class_of(Key, Sub, Super) :-
    (   nonvar(Sub),
        \+ s_class(Key, Sub)
    ->  (   Super = Sub
        ;   \+ oro_meta_namespace(Sub),
            rdf_equal(owl:'Thing', Super)
        )
    ;   s_sub(Key, Sub, Super)
    ).

%   sub_class_of(+Key, +Model, ?Sub, ?Super): sub_class_of/3, also
%   enumerating, when Sub is unbound, the classes only used as types,
%   which s_sub/3 does not hold.

sub_class_of(Key, Model, Sub, Super) :-
    (   nonvar(Sub)
    ->  sub_class_of(Key, Sub, Super)
    ;   s_sub(Key, Sub, Super)
    ;   type_only_sub(Key, Model, Sub, Super)
    ).

%   type_only_sub(+Key, +Model, -Sub, ?Super): Sub is a class of Model
%   unknown to the schema, only used as the type of something, and
%   Super one of its super-classes: itself or owl:Thing.

type_only_sub(Key, Model, Sub, Super) :-
    (   nonvar(Super),
        \+ rdf_equal(owl:'Thing', Super)
    ->  \+ s_class(Key, Super),           % only itself is below it
        class_key(Key, Model, Super),
        Sub = Super
    ;   findall(C, type_only_class(Key, Model, C), Classes0),
        sort(Classes0, Classes),
        member(Sub, Classes),
        sub_class_of(Key, Sub, Super)
    ).

%   type_only_class(+Key, +Model, -Class) is nondet: Class is the type
%   of something in Model and unknown to the schema tables Key (once
%   for each thing it types).

type_only_class(Key, Model, Class) :-
    rdf_equal(rdf:type, Type),
    oro_asserted(Model, _, Type, Class),
    \+ s_class(Key, Class),
    \+ meta_class(Class).

way(Key, P, Q, Dir) :-
    (   s_has_ways(Key, P)
    ->  s_way(Key, P, Q, Dir)
    ;   Q = P,
        Dir = fwd
    ).

same(Key, X, Y) :-
    (   s_same(Key, X, Members)
    ->  member(Y, Members)
    ;   Y = X
    ).

%!  oro_meta_namespace(+IRI) is semidet.
%
%   IRI is in the rdf, rdfs, owl or xsd namespace.

oro_meta_namespace(IRI) :-
    atom(IRI),
    (   rdf_equal(rdf:'', NS)
    ;   rdf_equal(rdfs:'', NS)
    ;   rdf_equal(owl:'', NS)
    ;   rdf_equal(xsd:'', NS)
    ),
    sub_atom(IRI, 0, _, _, NS),
    !.

		 /*******************************
		 *          ANCESTORS           *
		 *******************************/

%   The goals in progress of a derivation: anc(Depth, Goals).  push/3
%   fails if Goal is a variant of one of them or if the derivation is
%   nested too deep.

max_depth(64).

push(Goal, anc(D, Goals), anc(D1, [Goal|Goals])) :-
    max_depth(Max),
    D < Max,
    \+ ( member(G, Goals), G =@= Goal ),
    D1 is D + 1.

		 /*******************************
		 *           HOLDS              *
		 *******************************/

%!  oro_holds(+Model, ?S, ?P, ?O) is nondet.
%
%   The triple S-P-O is in the inference closure of Model.  Each
%   distinct triple is returned once; with S, P and O bound it is
%   semidet.  Literal objects match by value (`12` matches
%   `"12"^^xsd:integer`; strings ignore language tags).  Model is a
%   model's name or alias (`default`, the robot id), as for oro_type/3,
%   oro_subclass/3, oro_subproperty/3, oro_class/2 and
%   oro_individual/2 (the others of this module take a model).
%
%   @error existence_error(agent, Model) for an unknown model.

oro_holds(Model0, S0, P0, O0) :-
    oro_resource(S0, S),
    oro_resource(P0, P),
    oro_object(O0, O),
    holds_pinned(Model0, S, P, O).

%!  oro_holds_normal(+Model, ?S, ?P, ?O) is nondet.
%
%   As oro_holds/4, for S, P and O already normal: IRIs, rdf_db literal
%   terms or variables, as oro_resource/2 and oro_object/2 give them and
%   as the store's triples hold them.  For callers that evaluate many
%   patterns whose terms are normal by construction (oro_solve/2 binds
%   the variables of its patterns to terms of the store), so that the
%   names are not normalised again at each step.

oro_holds_normal(Model, S, P, O) :-
    holds_pinned(Model, S, P, O).

%   holds_pinned(+Name, ?S, ?P, ?O): oro_holds_normal/4 for the model
%   Name names (a model or an alias), the answers found in a pinned
%   region of the shared tables, then given one by one out of it, so
%   that a caller that keeps choice points does not hold the pin.

holds_pinned(Name, S, P, O) :-
    (   ground(S-P-O)
    ->  pinned(model_holds_ground(Name, S, P, O))
    ;   pinned(model_derivations(Name, S-P-O, S, P, O, Triples0)),
        sort(Triples0, Triples),
        member(S-P-O, Triples)
    ).

%   model_holds_ground(+Name, +S, +P, +O) and model_derivations(+Name,
%   ?Template, ?S, ?P, ?O, -Bag): holds_ground/5 and derivations/7 with
%   the shared schema tables of the model Name names (model_schema/3),
%   as one goal for pinned/1 (a conjunction would be compiled at each
%   call).

model_holds_ground(Name, S, P, O) :-
    model_schema(Name, Model, Key),
    holds_ground(Key, Model, S, P, O).

model_derivations(Name, Template, S, P, O, Bag) :-
    model_schema(Name, Model, Key),
    derivations(Key, Model, Template, S, P, O, Bag).

%!  oro_holds_keyed(+Key, +Model, ?S, ?P, ?O) is nondet.
%
%   As oro_holds_normal/4, with the schema tables Key of Model, as
%   oro_with_shared_schema/3 gives them (and in its Goal, so that they
%   are not freed meanwhile).  For a caller that evaluates many
%   patterns in one go (a join), which finds the tables once.

oro_holds_keyed(Key, Model, S, P, O) :-
    (   ground(S-P-O)
    ->  holds_ground(Key, Model, S, P, O)
    ;   derivations(Key, Model, S-P-O, S, P, O, Triples0),
        sort(Triples0, Triples),
        member(S-P-O, Triples)
    ).

%!  oro_holds_bag(+Model, ?Template, ?S, ?P, ?O, -Bag) is det.
%
%   Bag is the list of the instantiations of Template, a term sharing
%   variables with S, P and O (normal, as for oro_holds_normal/4), for
%   the triples S-P-O in the inference closure of Model, *with
%   repetitions*: one per derivation, in no particular order.  The
%   solutions of oro_holds_normal/4 without their sorting: for a caller
%   that sorts what it keeps of them anyway (a find of one pattern).

oro_holds_bag(Model, Template, S, P, O, Bag) :-
    (   ground(S-P-O)
    ->  findall(Template, pinned(model_holds_ground(Model, S, P, O)), Bag)
    ;   pinned(model_derivations(Model, Template, S, P, O, Bag))
    ).

%   holds_ground(+Key, +Model, +S, +P, +O): a check.  A type check, the
%   most frequent in joins, goes to has_type/5 at once.

holds_ground(Key, Model, S, P, O) :-
    rdf_equal(rdf:type, Type),
    (   P == Type
    ->  has_type(Key, Model, anc(0, []), S, O)
    ;   holds(Key, Model, anc(0, []), S, P, O)
    ),
    !.

%   derivations(+Key, +Model, ?Template, ?S, ?P, ?O, -Bag): Template for
%   each derivation of S-P-O, but those whose predicate is a blank node.

derivations(Key, Model, Template, S, P, O, Bag) :-
    findall(Template,
            ( holds(Key, Model, anc(0, []), S, P, O),
              \+ rdf_is_bnode(P)
            ),
            Bag).

holds(Key, Model, Anc, S, P, O) :-
    var(P),
    !,
    candidate_predicate(Key, Model, S, O, P),
    holds(Key, Model, Anc, S, P, O).
holds(Key, Model, Anc, S, P, O) :-
    special_predicate(P),
    !,
    special_holds(P, Key, Model, Anc, S, O).
holds(Key, Model, Anc, S, P, O) :-
    step(Key, Model, Anc, P, S, O).
holds(Key, Model, Anc, S, P, O) :-
    s_trans_way(Key, P, T, Dir),
    (   Dir == fwd
    ->  transitive(Key, Model, Anc, T, S, O)
    ;   transitive(Key, Model, Anc, T, O, S)
    ).

special_predicate(rdf:type).
special_predicate(rdfs:subClassOf).
special_predicate(rdfs:subPropertyOf).
special_predicate(owl:sameAs).

special_holds(P, Key, Model, Anc, S, O) :-
    rdf_equal(P, rdf:type),
    !,
    type(Key, Model, Anc, S, O).
special_holds(P, Key, Model, _, S, O) :-
    rdf_equal(P, rdfs:subClassOf),
    !,
    (   nonvar(S)
    ->  class_key(Key, Model, S),
        sub_class_of(Key, S, O)
    ;   sub_class_of(Key, Model, S, O)
    ).
special_holds(P, Key, _Model, _, S, O) :-
    rdf_equal(P, rdfs:subPropertyOf),
    !,
    s_subprop(Key, S, O).
special_holds(_SameAs, Key, Model, _, S, O) :-
    (   nonvar(S)
    ->  same_as_known(Key, Model, S),
        same(Key, S, O)
    ;   nonvar(O)
    ->  same_as_known(Key, Model, O),
        same(Key, O, S)
    ;   s_same(Key, S, Members),
        member(O, Members)
    ).

same_as_known(Key, Model, X) :-
    (   s_same(Key, X, _)
    ->  true
    ;   individual_key(Key, Model, X)
    ).

%   One step: an asserted edge implying P, through its ways, with
%   owl:sameAs substitution; or a virtual edge (hasValue, chains).

step(Key, Model, _, P, S, O) :-
    way(Key, P, Q, Dir),
    (   Dir == fwd
    ->  asserted_same(Key, Model, S, Q, O)
    ;   asserted_same(Key, Model, O, Q, S)
    ).
step(Key, Model, Anc, P, S, O) :-
    s_virtual_way(Key, P, Q, Dir),
    (   Dir == fwd
    ->  virtual_edge(Key, Model, Anc, Q, S, O)
    ;   virtual_edge(Key, Model, Anc, Q, O, S)
    ).

asserted_same(Key, Model, S, Q, O) :-
    (   s_has_same(Key)
    ->  same_in(Key, S, S1),
        same_in(Key, O, O1),
        asserted_match(Model, S1, Q, O1),
        same_out(Key, S1, S),
        same_out(Key, O1, O)
    ;   asserted_match(Model, S, Q, O)
    ).

same_in(Key, X, Y) :-
    (   var(X)
    ->  true
    ;   same(Key, X, Y)
    ).

same_out(Key, Y, X) :-
    (   var(X)
    ->  same(Key, Y, X)
    ;   once(same(Key, Y, X))           % X bound meanwhile: `X p X`
    ).

%   virtual_edge(+Key, +Model, +Anc, +Q, ?S, ?O): S Q O is derived by
%   a hasValue restriction (S is an instance of it) or a chain.

virtual_edge(Key, Model, Anc, Q, S, O) :-
    s_hv_edge(Key, Q, R, V),
    value_match(Key, V, O),
    (   var(S)
    ->  type(Key, Model, Anc, S, R)
    ;   atom(S),
        once(has_type(Key, Model, Anc, S, R))
    ).
virtual_edge(Key, Model, Anc, Q, S, O) :-
    s_chain(Key, Q, Links),
    push(chain(Q, S, O), Anc, Anc1),
    chain_holds(Key, Model, Anc1, Links, S, O).

value_match(Key, V, O) :-
    (   V = literal(_)
    ->  (   var(O)
        ->  O = V
        ;   O = literal(_),
            oro_literal_match(O, V)
        )
    ;   var(O)
    ->  same(Key, V, O)
    ;   once(same(Key, V, O))
    ).

%   A chain is walked from its bound end; intermediate nodes are
%   deduplicated.

chain_holds(Key, Model, Anc, Links, S, O) :-
    (   var(S),
        nonvar(O)
    ->  reverse(Links, Reversed),
        maplist(invert_link, Reversed, Inverted),
        chain_walk(Inverted, Key, Model, Anc, O, S)
    ;   chain_walk(Links, Key, Model, Anc, S, O)
    ).

invert_link(inverse(P), P) :-
    !.
invert_link(P, inverse(P)).

chain_walk([Link], Key, Model, Anc, X, Y) :-
    !,
    link_holds(Link, Key, Model, Anc, X, Y).
chain_walk([Link|Links], Key, Model, Anc, X, Y) :-
    findall(X-Z, ( link_holds(Link, Key, Model, Anc, X, Z),
                   atom(Z)
                 ), Pairs0),
    sort(Pairs0, Pairs),
    member(X-Z, Pairs),
    chain_walk(Links, Key, Model, Anc, Z, Y).

link_holds(inverse(P), Key, Model, Anc, X, Y) :-
    !,
    holds(Key, Model, Anc, Y, P, X).
link_holds(P, Key, Model, Anc, X, Y) :-
    holds(Key, Model, Anc, X, P, Y).

%   asserted_match(+Model, ?S, +Q, ?O): an asserted triple, literal
%   objects compared by value.

asserted_match(Model, S, Q, O) :-
    (   nonvar(O),
        O = literal(_)
    ->  literal_asserted(Model, S, Q, O)
    ;   oro_asserted(Model, S, Q, O)
    ).

literal_asserted(Model, S, Q, Pattern) :-
    (   nonvar(S)
    ->  oro_asserted(Model, S, Q, Literal),
        oro_literal_match(Pattern, Literal)
    ;   literal_key(Pattern, string(Text))
    ->  atom_string(Lex, Text),
        rdf(S, Q, literal(exact(Lex), Value)),
        Literal = literal(Value),
        oro_literal_match(Pattern, Literal),
        once(oro_asserted(Model, S, Q, Literal))
    ;   oro_asserted(Model, S, Q, Literal),
        oro_literal_match(Pattern, Literal)
    ).

%!  oro_literal_match(+Pattern, +Literal) is semidet.
%
%   The two literals have the same value: numbers compare numerically
%   whatever their numeric datatype, booleans by truth value, and
%   strings by their text, ignoring language tags and xsd:string.

oro_literal_match(Pattern, Literal) :-
    literal_key(Pattern, K1),
    literal_key(Literal, K2),
    same_key(K1, K2).

same_key(number(X), number(Y)) :-
    !,
    X =:= Y.
same_key(K, K).

literal_key(literal(Value), Key) :-
    value_key(Value, Key).

value_key(type(Type, Lex), Key) :-
    !,
    (   bare_type(Type, Kind),
        typed_key(Kind, Lex, Key0)
    ->  Key = Key0
    ;   atom_string(Lex, String),
        (   rdf_equal(Type, xsd:string)
        ->  Key = string(String)
        ;   Key = typed(Type, String)
        )
    ).
value_key(lang(_, Lex), string(String)) :-
    !,
    atom_string(Lex, String).
value_key(Lex, string(String)) :-
    atom_string(Lex, String).

typed_key(number, Lex, number(N)) :-
    atom_number(Lex, N).
typed_key(boolean, Lex, boolean(B)) :-
    boolean_lexical(Lex, B).

boolean_lexical(true, true).
boolean_lexical('1', true).
boolean_lexical(false, false).
boolean_lexical('0', false).

bare_type(Type, number) :-
    oro_numeric_datatype(Type, _).
bare_type(xsd:boolean, boolean).

%!  oro_datatype_member(+Literal, +Filler) is semidet.
%
%   Literal is a value of Filler, a datatype(Datatype, Facets) filler
%   of oro_class_definition/3: any literal for rdfs:Literal, a number
%   for a numeric xsd datatype (within the range facets), a boolean for
%   xsd:boolean, a string for xsd:string.

oro_datatype_member(Literal, datatype(DT, Facets)) :-
    Literal = literal(_),
    literal_key(Literal, Key),
    datatype_key(DT, Key),
    \+ memberchk(unsupported, Facets),
    forall(member(Facet-Bound, Facets),
           facet_holds(Facet, Key, Bound)).

datatype_key(DT, _) :-
    rdf_equal(DT, rdfs:'Literal'),
    !.
datatype_key(DT, Key) :-
    (   bare_type(DT, Kind)
    ->  functor(Key, Kind, 1)
    ;   rdf_equal(DT, xsd:string)
    ->  Key = string(_)
    ;   Key = typed(DT, _)
    ).

facet_holds(Facet, number(X), Bound) :-
    literal_key(Bound, number(B)),
    facet_compare(Facet, X, B).

facet_compare(min_inclusive, X, B) :- X >= B.
facet_compare(max_inclusive, X, B) :- X =< B.
facet_compare(min_exclusive, X, B) :- X > B.
facet_compare(max_exclusive, X, B) :- X < B.

%   Transitive closure of the edges implying T, breadth first, from a
%   bound end.  With both ends unbound, from every subject of an edge.

transitive(Key, Model, Anc, T, S, O) :-
    (   nonvar(S)
    ->  reach(Key, Model, Anc, T, fwd, S, O)
    ;   nonvar(O)
    ->  reach(Key, Model, Anc, T, bwd, O, S)
    ;   findall(S0, step(Key, Model, Anc, T, S0, _), Starts0),
        sort(Starts0, Starts),
        member(S, Starts),
        reach(Key, Model, Anc, T, fwd, S, O)
    ).

reach(Key, Model, Anc, T, Dir, From, To) :-
    (   nonvar(To)
    ->  reach_set(Key, Model, Anc, T, Dir, [From], [], To, Reached),
        memberchk(To, Reached)
    ;   reach_set(Key, Model, Anc, T, Dir, [From], [], _, Reached),
        member(To, Reached)
    ).

%   reach_set(..., +Queue, +Seen, ?Goal, -Reached): stops early once
%   Goal (if bound) is reached.

reach_set(_, _, _, _, _, [], Seen, _, Seen) :- !.
reach_set(_, _, _, _, _, _, Seen, Goal, Seen) :-
    nonvar(Goal),
    memberchk(Goal, Seen),
    !.
reach_set(Key, Model, Anc, T, Dir, [X|Queue], Seen, Goal, Reached) :-
    findall(Y, ( next(Key, Model, Anc, T, Dir, X, Y),
                 Y \= literal(_),
                 \+ memberchk(Y, Seen)
               ), Next0),
    sort(Next0, Next),
    append(Seen, Next, Seen1),
    append(Queue, Next, Queue1),
    reach_set(Key, Model, Anc, T, Dir, Queue1, Seen1, Goal, Reached).

next(Key, Model, Anc, T, fwd, X, Y) :-
    step(Key, Model, Anc, T, X, Y).
next(Key, Model, Anc, T, bwd, X, Y) :-
    step(Key, Model, Anc, T, Y, X).

%   Predicates that may hold between S and O when P is unbound.

candidate_predicate(Key, Model, S, O, P) :-
    findall(P0, candidate_predicate_(Key, Model, S, O, P0), Ps0),
    sort(Ps0, Ps),
    member(P, Ps).

candidate_predicate_(Key, Model, S, O, P) :-
    (   nonvar(S)
    ->  same_in(Key, S, S1),
        oro_asserted(Model, S1, Q, _),
        used_as(Key, Q, fwd, P)
    ;   nonvar(O)
    ->  same_in(Key, O, O1),
        oro_asserted(Model, _, Q, O1),
        used_as(Key, Q, fwd, P)
    ;   oro_asserted(Model, _, Q, _),
        used_as(Key, Q, fwd, P)
    ).
candidate_predicate_(Key, Model, S, O, P) :-
    (   nonvar(S)
    ->  same_in(Key, S, S1),
        oro_asserted(Model, _, Q, S1)
    ;   nonvar(O)
    ->  same_in(Key, O, O1),
        oro_asserted(Model, O1, Q, _)
    ),
    used_as(Key, Q, bwd, P).
candidate_predicate_(Key, _, _, _, P) :-
    s_virtual_way(Key, P, _, _).
candidate_predicate_(_, _, _, _, P) :-
    special_predicate(P).

used_as(Key, Q, Dir, P) :-
    (   s_way(Key, P, Q, Dir)
    *-> true
    ;   Dir == fwd,
        P = Q
    ).

		 /*******************************
		 *            TYPES             *
		 *******************************/

type(Key, Model, Anc, X, C) :-
    (   nonvar(X)
    ->  (   nonvar(C)
        ->  has_type(Key, Model, Anc, X, C),
            !
        ;   types_of(Key, Model, Anc, X, Types),
            member(C, Types)
        )
    ;   nonvar(C)
    ->  instances_of(Key, Model, Anc, C, Instances),
        member(X, Instances)
    ;   findall(X0, individual_key(Key, Model, X0), Xs),
        member(X, Xs),
        types_of(Key, Model, Anc, X, Types),
        member(C, Types)
    ).

has_type(Key, Model, _, X, C) :-
    rdf_equal(owl:'Thing', C),
    !,
    same(Key, X, X1),
    individual_key(Key, Model, X1).
has_type(Key, Model, Anc, X, C) :-
    rdf_equal(rdf:type, Type),
    (   same(Key, X, X1),
        oro_asserted(Model, X1, Type, D),
        sub_class_of(Key, D, C)
    ;   s_implied(Key, C),
        implied_type(Key, Model, Anc, X, C)
    ).

implied_type(Key, Model, _, X, C) :-
    same(Key, X, X1),
    (   s_subj_implies(Key, Q, C),
        oro_asserted(Model, X1, Q, _)
    ;   s_obj_implies(Key, Q, C),
        oro_asserted(Model, _, Q, X1)
    ).
implied_type(Key, Model, Anc, X, C) :-
    s_entry_sub(Key, D, C),
    entry_member(Key, Model, Anc, X, D).

%   entry_member(+Key, +Model, +Anc, +X, +D): X meets a condition of
%   the entry class D.

entry_member(Key, Model, Anc, X, D) :-
    atom(X),
    push(type(X, D), Anc, Anc1),
    s_entry(Key, D, Cond),
    entry_holds(Cond, Key, Model, Anc1, X),
    !.

entry_holds(value(Q, V), Key, Model, Anc, X) :-
    holds(Key, Model, Anc, X, Q, V),
    !.
entry_holds(some(Q, Filler), Key, Model, Anc, X) :-
    holds(Key, Model, Anc, X, Q, Y),
    filler_member(Filler, Key, Model, Anc, Y),
    !.
entry_holds(all_of(Ms), Key, Model, Anc, X) :-
    forall(member(M, Ms),
           has_type(Key, Model, Anc, X, M)).
entry_holds(one_of(Xs), Key, _, _, X) :-
    same(Key, X, X1),
    memberchk(X1, Xs),
    !.
entry_holds(avf(Q, R), Key, Model, Anc, X) :-
    holds(Key, Model, Anc, Z, Q, X),
    atom(Z),
    has_type(Key, Model, Anc, Z, R),
    !.
entry_holds(vsubj(Q), Key, Model, Anc, X) :-
    virtual_edge(Key, Model, Anc, Q, X, _),
    !.
entry_holds(vobj(Q), Key, Model, Anc, X) :-
    virtual_edge(Key, Model, Anc, Q, _, X),
    !.

filler_member(thing, _, _, _, _).
filler_member(class(C), Key, Model, Anc, Y) :-
    atom(Y),
    has_type(Key, Model, Anc, Y, C),
    !.
filler_member(datatype(DT, Facets), _, _, _, Y) :-
    oro_datatype_member(Y, datatype(DT, Facets)).

types_of(Key, Model, Anc, X, Types) :-
    rdf_equal(rdf:type, Type),
    findall(C, ( same(Key, X, X1),
                 (   oro_asserted(Model, X1, Type, D),
                     sub_class_of(Key, D, C)
                 ;   oro_asserted(Model, X1, Q, _),
                     s_subj_implies(Key, Q, C)
                 ;   oro_asserted(Model, _, Q, X1),
                     s_obj_implies(Key, Q, C)
                 ;   individual_key(Key, Model, X1),
                     rdf_equal(owl:'Thing', C)
                 )
               ), Types0),
    sort(Types0, Base),
    (   s_has_entries(Key),
        atom(X)
    ->  findall(C, ( s_entry_class(Key, D),
                     \+ ord_memberchk(D, Base),
                     entry_member(Key, Model, Anc, X, D),
                     s_sub(Key, D, C)
                   ), Extra0),
        sort(Extra0, Extra),
        ord_union(Base, Extra, Types)
    ;   Types = Base
    ).

instances_of(Key, Model, _, C, Instances) :-
    rdf_equal(owl:'Thing', C),
    !,
    findall(X, individual_key(Key, Model, X), Instances).
instances_of(Key, Model, Anc, C, Instances) :-
    rdf_equal(rdf:type, Type),
    findall(X, ( (   s_sub(Key, D, C),
                     oro_asserted(Model, X1, Type, D)
                 ;   \+ s_class(Key, C),
                     oro_asserted(Model, X1, Type, C)
                 ;   s_subj_implies(Key, Q, C),
                     oro_asserted(Model, X1, Q, _)
                 ;   s_obj_implies(Key, Q, C),
                     oro_asserted(Model, _, Q, X1),
                     atom(X1)
                 ),
                 same(Key, X1, X)
               ), Instances0),
    sort(Instances0, Base),
    (   s_has_entries(Key),
        once(s_entry_sub(Key, _, C)),
        push(inst(C), Anc, Anc1)
    ->  findall(X, ( s_entry_sub(Key, D, C),
                     s_entry(Key, D, Cond),
                     entry_instance(Cond, Key, Model, Anc1, D, X)
                   ), Extra0),
        sort(Extra0, Extra),
        ord_union(Base, Extra, Instances)
    ;   Instances = Base
    ).

%   entry_instance(+Condition, +Key, +Model, +Anc, +D, -X): X is an
%   instance of the entry class D through Condition.

entry_instance(value(Q, V), Key, Model, Anc, _, X) :-
    holds(Key, Model, Anc, X, Q, V),
    atom(X).
entry_instance(some(Q, Filler), Key, Model, Anc, _, X) :-
    (   Filler = class(F)
    ->  type(Key, Model, Anc, Y, F),
        holds(Key, Model, Anc, X, Q, Y)
    ;   holds(Key, Model, Anc, X, Q, Y),
        filler_member(Filler, Key, Model, Anc, Y)
    ),
    atom(X).
entry_instance(all_of([M|_]), Key, Model, Anc, D, X) :-
    type(Key, Model, Anc, X, M),
    entry_member(Key, Model, Anc, X, D).
entry_instance(one_of(Xs), Key, _, _, _, X) :-
    member(X0, Xs),
    same(Key, X0, X).
entry_instance(avf(Q, R), Key, Model, Anc, _, X) :-
    type(Key, Model, Anc, Z, R),
    holds(Key, Model, Anc, Z, Q, X),
    atom(X).
entry_instance(vsubj(Q), Key, Model, Anc, _, X) :-
    virtual_edge(Key, Model, Anc, Q, X, _),
    atom(X).
entry_instance(vobj(Q), Key, Model, Anc, _, X) :-
    virtual_edge(Key, Model, Anc, Q, _, X),
    atom(X).

%   Individuals: typed with a non-meta class, or subject or object of
%   an instance-level triple.

individual_key(Key, Model, X) :-
    nonvar(X),
    !,
    same(Key, X, X1),
    individual_evidence(Model, X1),
    !.
individual_key(Key, Model, X) :-
    findall(X0, individual_candidate(Model, X0), Xs0),
    sort(Xs0, Xs1),
    include(is_individual(Model), Xs1, Xs2),
    findall(X1, ( member(X0, Xs2), same(Key, X0, X1) ), Xs3),
    sort(Xs3, Xs),
    member(X, Xs).

is_individual(Model, X) :-
    individual_evidence(Model, X),
    !.

%   individual_evidence(+Model, +X): X is typed by a class, or is the
%   subject or object of a property that is not of the vocabulary of
%   RDF or OWL; but the header of an ontology (`<iri> a owl:Ontology`)
%   is not an individual, whatever annotations it has.

individual_evidence(Model, X) :-
    \+ ontology_header(Model, X),
    evidence(Model, X).

evidence(Model, X) :-
    rdf_equal(rdf:type, Type),
    oro_asserted(Model, X, Type, C),
    \+ meta_class(C).
evidence(Model, X) :-
    oro_asserted(Model, X, Q, _),
    instance_predicate(Q).
evidence(Model, X) :-
    oro_asserted(Model, _, Q, X),
    instance_predicate(Q).

ontology_header(Model, X) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:'Ontology', Ontology),
    oro_asserted(Model, X, Type, Ontology).

individual_candidate(Model, X) :-
    oro_asserted(Model, S, Q, O),
    (   rdf_equal(rdf:type, Q)
    ->  \+ meta_class(O),
        X = S
    ;   instance_predicate(Q)
    ->  (   X = S
        ;   atom(O),
            X = O
        )
    ).

instance_predicate(Q) :-
    (   \+ oro_meta_namespace(Q)
    ->  true
    ;   rdf_equal(Q, owl:sameAs)
    ;   rdf_equal(Q, owl:differentFrom)
    ).

meta_class(C) :-
    oro_schema_class(C).
meta_class(owl:'Ontology').
meta_class(owl:'AllDifferent').
meta_class(owl:'AllDisjointClasses').
meta_class(owl:'AllDisjointProperties').
meta_class(rdfs:'Datatype').
meta_class(rdf:'List').
meta_class(rdf:'Statement').

		 /*******************************
		 *          PUBLIC API          *
		 *******************************/

%!  oro_type(+Model, ?X, ?Class) is nondet.
%
%   X is an instance of Class in the inference closure of Model.

oro_type(Model, X, Class) :-
    rdf_equal(rdf:type, Type),
    oro_holds(Model, X, Type, Class).

%!  oro_subclass(+Model, ?Sub, ?Super) is nondet.
%
%   Sub is a (reflexive, transitive) sub-class of Super in Model;
%   every class is a sub-class of owl:Thing.  Intersections are below
%   their members and members of unions below the union.

oro_subclass(Model0, Sub0, Super0) :-
    oro_resource(Sub0, Sub),
    oro_resource(Super0, Super),
    pinned(subclass(Model0, Sub, Super)).

%   subclass/3, subproperty/3, class/2, property/3, individual/2,
%   same_individual/3: the bodies of the public predicates, as goals of
%   their own for pinned/1 (a conjunction given to it would be compiled
%   again on every call).

subclass(Model0, Sub, Super) :-
    model_schema(Model0, Model, Key),
    (   nonvar(Sub), nonvar(Super)
    ->  once(sub_class_of(Key, Sub, Super))
    ;   sub_class_of(Key, Model, Sub, Super)
    ).

%!  oro_subproperty(+Model, ?Sub, ?Super) is nondet.
%
%   Sub is a (reflexive, transitive) sub-property of Super in Model.

oro_subproperty(Model0, Sub0, Super0) :-
    oro_resource(Sub0, Sub),
    oro_resource(Super0, Super),
    pinned(subproperty(Model0, Sub, Super)).

subproperty(Model0, Sub, Super) :-
    model_schema(Model0, _, Key),
    (   nonvar(Sub),
        \+ s_prop(Key, Sub, _)
    ->  Super = Sub
    ;   nonvar(Sub), nonvar(Super)
    ->  once(s_subprop(Key, Sub, Super))
    ;   s_subprop(Key, Sub, Super)
    ).

%!  oro_class(+Model, ?Class) is nondet.
%
%   Class is a class of Model: declared, used in the class hierarchy,
%   in a class expression, as a domain or range, or as the type of
%   something.

oro_class(Model0, Class0) :-
    oro_resource(Class0, Class),
    pinned(class(Model0, Class)).

class(Model0, Class) :-
    model_schema(Model0, Model, Key),
    (   nonvar(Class)
    ->  class_key(Key, Model, Class)
    ;   findall(C, ( s_class(Key, C)
                   ; type_only_class(Key, Model, C)
                   ), Classes0),
        sort(Classes0, Classes),
        member(Class, Classes)
    ).

class_key(Key, Model, Class) :-
    (   s_class(Key, Class)
    ->  true
    ;   rdf_equal(rdf:type, Type),
        once(oro_asserted(Model, _, Type, Class)),
        \+ meta_class(Class)
    ).

%!  oro_property(+Model, ?Property, ?Kind) is nondet.
%
%   Property is a property of Model, of Kind `object`, `datatype`,
%   `annotation` or `other`.  An undeclared kind is taken from the
%   schema (an inverse is an object property, a sub-property has the
%   kind of its super-property, a datatype range makes a datatype
%   property), else from the values, as OWL reasoners do: `datatype`
%   if the property has a literal value, `object` otherwise.

oro_property(Model, Property0, Kind) :-
    oro_resource(Property0, Property),
    pinned(property(Model, Property, Kind)).

property(Model, Property, Kind) :-
    schema(Model, Key),
    (   nonvar(Property)
    ->  (   s_prop(Key, Property, Kind0)
        ->  true
        ;   once(oro_asserted(Model, _, Property, _))
        ->  Kind0 = other
        ),
        used_kind(Model, Property, Kind0, Kind)
    ;   findall(P-K, s_prop(Key, P, K), Declared),
        findall(P-other, ( rdf_current_predicate(P),
                           \+ s_prop(Key, P, _),
                           \+ oro_meta_namespace(P),
                           once(oro_asserted(Model, _, P, _))
                         ), Used),
        append(Declared, Used, All0),
        sort(All0, All),
        member(Property-Kind0, All),
        used_kind(Model, Property, Kind0, Kind)
    ).

used_kind(Model, Property, other, Kind) :-
    !,
    (   rdf(S, Property, literal(L)),
        oro_asserted(Model, S, Property, literal(L))
    ->  Kind = datatype
    ;   once(oro_asserted(Model, _, Property, _))
    ->  Kind = object
    ;   Kind = other
    ).
used_kind(_, _, Kind, Kind).

%!  oro_individual(+Model, ?X) is nondet.
%
%   X is a named individual of Model (an instance of owl:Thing).

oro_individual(Model0, X0) :-
    oro_resource(X0, X),
    pinned(individual(Model0, X)).

individual(Model0, X) :-
    model_schema(Model0, Model, Key),
    individual_key(Key, Model, X).

%!  oro_same_individual(+Model, +X, -Y) is multi.
%
%   Y is X or an individual owl:sameAs X.

oro_same_individual(Model, X0, Y) :-
    oro_resource(X0, X),
    pinned(same_individual(Model, X, Y)).

same_individual(Model, X, Y) :-
    schema(Model, Key),
    same(Key, X, Y).

%!  oro_has_same_individuals(+Model) is semidet.
%
%   Some individual of Model has other names (owl:sameAs).  If not,
%   oro_same_individual/3 gives every individual itself only.

oro_has_same_individuals(Model) :-
    pinned(has_same_individuals(Model)).

has_same_individuals(Model) :-
    schema(Model, Key),
    once(s_same(Key, _, _)).

%!  oro_functional_property(+Model, ?Property) is nondet.
%
%   Property is declared owl:FunctionalProperty in Model.

oro_functional_property(Model, Property) :-
    pinned(functional_property(Model, Property)).

functional_property(Model, Property) :-
    schema(Model, Key),
    s_functional(Key, Property).

%!  oro_transitive_property(+Model, ?Property) is nondet.
%
%   Property is declared owl:TransitiveProperty in Model.

oro_transitive_property(Model, Property) :-
    pinned(transitive_property(Model, Property)).

transitive_property(Model, Property) :-
    schema(Model, Key),
    s_transitive(Key, Property).

%!  oro_property_characteristic(+Model, ?Property, ?Characteristic) is nondet.
%
%   Property is declared with Characteristic in Model: `functional`,
%   `inverse_functional`, `asymmetric`, `irreflexive` or `reflexive`
%   (transitive and symmetric properties have their own predicates).

oro_property_characteristic(Model, Property, Characteristic) :-
    pinned(property_characteristic(Model, Property, Characteristic)).

property_characteristic(Model, Property, Characteristic) :-
    schema(Model, Key),
    s_char(Key, Property, Characteristic).

%!  oro_disjoint_classes(+Model, ?Class1, ?Class2) is nondet.
%
%   Class1 and Class2 are declared disjoint (owl:disjointWith,
%   owl:complementOf or owl:AllDisjointClasses), either way.

oro_disjoint_classes(Model, Class1, Class2) :-
    pinned(( schema(Model, Key),
             s_disjoint(Key, Class1, Class2)
           )).

%!  oro_disjoint_properties(+Model, ?Property1, ?Property2) is nondet.
%
%   The two properties are declared disjoint (owl:propertyDisjointWith
%   or owl:AllDisjointProperties), either way.

oro_disjoint_properties(Model, Property1, Property2) :-
    pinned(( schema(Model, Key),
             s_prop_disjoint(Key, Property1, Property2)
           )).

%!  oro_class_definition(+Model, ?Class, ?Definition) is nondet.
%
%   Class (usually a blank node) is defined in Model by Definition:
%
%     - has_value(P, V): owl:hasValue restriction;
%     - some_values(P, Filler), all_values(P, Filler):
%       owl:someValuesFrom, owl:allValuesFrom restrictions; Filler is
%       `thing`, class(C) or datatype(Datatype, Facets), Facets a list
%       of min_inclusive-Literal, max_inclusive-Literal,
%       min_exclusive-Literal, max_exclusive-Literal or `unsupported`;
%     - intersection(Classes), union(Classes), one_of(Individuals).

oro_class_definition(Model, Class, Definition) :-
    pinned(( schema(Model, Key),
             s_def(Key, Class, Definition)
           )).

%!  oro_property_chain(+Model, ?Property, ?Links) is nondet.
%
%   The chain Links (a list of properties P or inverse(P)) implies
%   Property (owl:propertyChainAxiom).

oro_property_chain(Model, Property, Links) :-
    pinned(( schema(Model, Key),
             s_chain(Key, Property, Links)
           )).

%!  oro_property_way(+Model, +Property, ?Implying, ?Dir) is nondet.
%
%   An edge `S Implying O` implies `S Property O` (Dir `fwd`) or
%   `O Property S` (Dir `bwd`), through sub-properties, equivalent and
%   inverse properties and symmetry.  Every property implies itself.

oro_property_way(Model, Property, Implying, Dir) :-
    must_be(atom, Property),
    pinned(property_way(Model, Property, Implying, Dir)).

property_way(Model, Property, Implying, Dir) :-
    schema(Model, Key),
    way(Key, Property, Implying, Dir).

%!  oro_pattern_dependencies(+Model, +Triples, -Predicates) is det.
%
%   Predicates is the ordered set of predicates whose asserted triples
%   can change the solutions of the patterns Triples in Model, through
%   sub-properties, inverses, symmetry, transitivity, domains, ranges
%   and owl:sameAs (and rdf:type for an rdfs:subClassOf pattern: a
%   class only used as a type is a sub-class of owl:Thing); it is
%   `[any]` when any triple can (a variable predicate, a variable
%   class, owl:Thing, a class or a property that class expressions or
%   chains derive).  Schema changes are not covered: they can change
%   anything.

oro_pattern_dependencies(Model, Triples, Predicates) :-
    must_be(list, Triples),
    pinned(( schema(Model, Key),
             (   member(rdf(_, P, O), Triples),
                 depends_on_any(Key, P, O)
             ->  Predicates = [any]
             ;   findall(Q, ( member(rdf(_, P, O), Triples),
                              pattern_dependency(Key, P, O, Q)
                            ), Qs),
                 rdf_equal(owl:sameAs, SameAs),
                 sort([SameAs|Qs], Predicates)
             )
           )).

depends_on_any(_, P, _) :-
    var(P),
    !.
depends_on_any(Key, P, O) :-
    rdf_equal(P, rdf:type),
    !,
    (   var(O)
    ->  true
    ;   rdf_equal(O, owl:'Thing')
    ->  true
    ;   s_entry_sub(Key, _, O)
    ->  true
    ).
depends_on_any(Key, P, _) :-
    (   s_virtual_way(Key, P, _, _)
    ->  true
    ;   s_trans_way(Key, P, T, _),
        s_virtual_way(Key, T, _, _)
    ->  true
    ).

pattern_dependency(Key, P, O, Q) :-
    rdf_equal(P, rdf:type),
    !,
    (   Q = P
    ;   s_subj_implies(Key, Q, O)
    ;   s_obj_implies(Key, Q, O)
    ).
pattern_dependency(Key, P, O, Q) :-
    rdf_equal(P, rdfs:subClassOf),
    !,
    (   var(O)                          % a class only used as a type is
    ->  true                            % below itself and owl:Thing
    ;   rdf_equal(O, owl:'Thing')
    ->  true
    ;   \+ s_class(Key, O)
    ),
    rdf_equal(rdf:type, Q).
pattern_dependency(_, P, _, _) :-
    rdf_equal(P, rdfs:subPropertyOf),
    !,
    fail.
pattern_dependency(Key, P, _, Q) :-
    (   way(Key, P, Q, _)
    ;   s_trans_way(Key, P, T, _),
        way(Key, T, Q, _)
    ).
