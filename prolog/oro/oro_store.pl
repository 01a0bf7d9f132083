:- module(oro_store,
          [ oro_graph/3,                % +Model, +Layer, -Graph
            oro_shared_graph/2,         % +Layer, -Graph
            oro_graph_layer/3,          % ?Graph, ?Model, ?Layer
            oro_model/1,                % ?Model
            oro_create_model/1,         % +Model
            oro_model_alias/2,          % ?Alias, ?Model
            oro_add_model_alias/2,      % +Alias, +Model
            oro_resolve_model/2,        % +Name, -Model
            oro_asserted/4,             % +Model, ?S, ?P, ?O
            oro_stored_term/4,          % +S, +P, +O, -Stored
            oro_asserted_count/2,       % +Model, -Count
            oro_store_assert/3,         % +Model, +Triples, +Profile
            oro_profile_layer/2,        % +Profile, -LayerProfile
            oro_store_retract/2,        % +Model, +Triples
            oro_store_forget/3,         % +Model, +Profile, +Triples
            oro_store_write/2,          % +Action, :Goal
            oro_schema_generation/1,    % -Generation
            oro_store_schema_pending/0,
            oro_schema_triple/2,        % +P, +O
            oro_schema_class/1,         % ?Class
            oro_load_ontology/1,        % +File
            oro_load_ontology/2,        % +File, +Options
            oro_ontology_graph/1,       % ?Graph
            oro_store_sizes/1,          % -Sizes
            oro_wipe_models/0,
            oro_store_reset/0,
            oro_store_attach/1,         % +Directory
            oro_store_detach/0,
            oro_scratch_graph/1,        % +Graph
            oro_named/2,                % +LowerLocalName, -IRI
            oro_store_read/1,           % :Goal
            oro_store_rebuild/0,
            oro_store_gate_exempt/0,
            oro_store_try_read/1,       % :Goal
            oro_drain_queue/2           % +Queue, -Messages
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(semweb/turtle)).
:- use_module(library(semweb/rdf_ntriples)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(debug)).
:- use_module(library(settings)).
:- use_module(library(option)).
:- use_module(library(aggregate)).
:- use_module(library(uri), [uri_file_name/2]).
:- use_module(library(oro/oro_persist)).
:- use_module(library(oro/oro_messages)).
:- use_module(library(oro/oro_names), [oro_local_name/2]).

:- meta_predicate
    oro_store_write(+, 0),
    oro_store_read(0),
    oro_store_try_read(0).

/** <module> The store: graphs, models and asserted triples

All triples live in rdf_db.  This module owns the naming of graphs and
is the only place that writes user triples.

  - The *ontology layer* is one read-only graph per loaded ontology
    file, shared by every model.
  - A *model* is the knowledge of one agent: the robot is `myself`
    (aliases `default` and the robot id).  A model owns one graph per
    memory profile (`profile(longterm)`, ...) holding what was asserted
    in it, and a `mask` graph listing the ontology triples it removed.
    A triple is *visible* in a model when it is in one of the model's
    profile graphs, or in the ontology layer and not masked.

Every change runs in one rdf_transaction/2 under the `oro_write`
mutex, so writes are serialised, atomic, and seen by rdf_monitor/2 as
one change.  Changes to schema triples bump a generation counter that
the reasoner uses to know when its schema closures are stale.

## The GC pin

rdf_db (SWI-Prolog 9.0.4) reclaims a deleted triple once no query or
snapshot may still see it, but its garbage collector decides that from
the oldest snapshot *when a pass starts*, and with no snapshot at all
it takes every deleted triple for garbage, including the ones deleted
while the pass runs.  A snapshot taken during such a pass then loses,
from some index chains, the triples deleted after it was taken: rdf/3
misses them in that snapshot though rdf/4 by subject finds them.  The
event watchers read the snapshots of committed changes, and lost
events that way (one run in a few hundred of the events stress test).

This module therefore keeps one snapshot alive at all times, the *GC
pin*: the collector then never counts as garbage a triple deleted after
the pin was taken, so never one a later snapshot (or query) may see.
The pin is renewed, under the `oro_write` mutex, after every write and
reset, so it delays the reclaiming of a deleted triple until the next
write at most (rdf_db reclaims a triple once every snapshot is newer
than the generation that deleted it); a rebuild lets go of it while
rdf_db is reset.

## Writes leave no clause behind

A write asserts and retracts no clause of its own (but for the names
of IRIs it leaves unused): what it notes as it runs is kept in the
writing thread's global variables (`oro_store_writing`,
`oro_store_maybe_unused`), not in thread-local facts, and the GC pin is
the one message of a queue.  The events monitor and the consistency
log do the same.

Every clause retracted is work for SWI-Prolog's clause garbage
collector.  Once a program has erased clauses it held references to
(set_setting/2 does, and the server calls it),
SWI-Prolog 9.0.4 also runs atom GC, which scans every atom, with each
run of that collector.  With three or four clauses retracted a write,
a server adding one statement at a time ran both collectors every 12
writes; they took 12 to 37 us of CPU a write (measured with a
benchmark since retired, bench/bench_writes.pl: see git log).
*/

:- dynamic
    model_graph/3,                  % Graph, Model, Layer
    model_alias/2,                  % Alias, Model
    ontology_graph/1,               % Graph
    name_of/2.                      % IRI, LowerLocalName

%!  oro_graph(+Model, +Layer, -Graph) is det.
%
%   The rdf_db graph holding Layer of Model.  Layer is `mask` or
%   profile(Profile) with Profile one of `longterm`, `shortterm`,
%   `episodic` or `timed` (facts given a lifespan of their own, see
%   oro_memory).  The graphs of an existing model are those named when
%   it was created (create_model/1).  Graph names are spelled by
%   graph_name/3 alone, through model_graph_of/3 for a model's and
%   oro_shared_graph/2 for the others.

oro_graph(Model, Layer, Graph) :-
    (   model_graph(Graph0, Model, Layer)   % named when it was created
    ->  Graph = Graph0
    ;   model_key(Model, Key),
        model_graph_of(Key, Layer, Graph)
    ).

model_graph_of(Key, Layer, Graph) :-
    layer_name(Layer, Name),
    graph_name(Key, Name, Graph).

%!  oro_shared_graph(+Layer, -Graph) is det.
%
%   The rdf_db graph of a layer that belongs to no model: ontology(N),
%   the N-th graph of the ontology layer, or scratch(Name), a temporary
%   graph (see oro_scratch_graph/1).  Neither can be taken for a model
%   graph: their layer names are none of a model's.

oro_shared_graph(ontology(N), Graph) :-
    must_be(positive_integer, N),
    graph_name(ontology, N, Graph).
oro_shared_graph(scratch(Name), Graph) :-
    must_be(atom, Name),
    graph_name(scratch, Name, Graph).

graph_name(Owner, Layer, Graph) :-
    atomic_list_concat(['oro:', Owner, '#', Layer], Graph).

%   model_key(+Model, -Key): the name of Model in its graphs' names.
%   With a database attached, each graph is journaled in a file named
%   after the graph, its characters but ASCII letters, digits and `_`
%   written as %XX (library(semweb/rdf_persistency)), and a file name
%   has at most 255 bytes.  A model whose name would take more than
%   200 bytes there (an agent named by a long IRI) is named by `~` and
%   the MD5 digest of its name; the commit log remembers which model
%   that is (model_key/2 records, see create_model/1).

model_key(Model, Key) :-
    atom_length(Model, Length),
    (   Length =< 16                    % 16 characters: at most 192 bytes
    ->  Key = Model
    ;   atom_codes(Model, Codes),
        foldl(encoded_bytes, Codes, 0, Bytes),
        Bytes =< 200
    ->  Key = Model
    ;   rdf_atom_md5(Model, 1, Digest),
        atom_concat(~, Digest, Key)
    ).

encoded_bytes(C, N0, N) :-
    (   C < 128,
        ( code_type(C, alnum) ; C == 0'_ )
    ->  N is N0 + 1
    ;   C < 0x80
    ->  N is N0 + 3
    ;   C < 0x800
    ->  N is N0 + 6
    ;   C < 0x10000
    ->  N is N0 + 9
    ;   N is N0 + 12
    ).

layer_name(profile(Profile), Profile).
layer_name(mask, mask).

%!  oro_profile_layer(+Profile, -LayerProfile) is det.
%
%   The profile whose graph holds the facts of memory Profile: a fact
%   given its own lifespan(Seconds) lives in the graph of `timed`.

oro_profile_layer(lifespan(_), timed) :-
    !.
oro_profile_layer(Profile, Profile).

%!  oro_graph_layer(?Graph, ?Model, ?Layer) is nondet.
%
%   True when Graph is the graph of Layer of the existing Model.

oro_graph_layer(Graph, Model, Layer) :-
    model_graph(Graph, Model, Layer).

%!  oro_ontology_graph(?Graph) is nondet.
%
%   Graph is a graph of the (read-only, shared) ontology layer.

oro_ontology_graph(Graph) :-
    ontology_graph(Graph).

%!  oro_store_sizes(-Sizes) is det.
%
%   Sizes lists the triples of each part of the store, as
%   size(Model, Layer, Triples) for every model graph (Layer is
%   profile(longterm), profile(shortterm), profile(episodic) or mask)
%   and size(ontology, File, Triples) for every ontology file, in
%   standard order.

oro_store_sizes(Sizes) :-
    findall(size(Part, Layer, Triples),
            ( store_part(Graph, Part, Layer),
              graph_size(Graph, Triples)
            ),
            Sizes0),
    msort(Sizes0, Sizes).

store_part(Graph, Model, Layer) :-
    model_graph(Graph, Model, Layer).
store_part(Graph, ontology, File) :-
    ontology_graph(Graph),
    (   rdf_graph_property(Graph, source(Source)),
        uri_file_name(Source, File0)
    ->  File = File0
    ;   File = Graph
    ).

graph_size(Graph, Triples) :-
    (   rdf_graph_property(Graph, triples(Triples0))
    ->  Triples = Triples0
    ;   Triples = 0
    ).

oro_model(Model) :-
    model_graph(_, Model, profile(longterm)).

%!  oro_create_model(+Model) is det.
%
%   Create the graphs of Model if it does not exist yet.

oro_create_model(Model) :-
    must_be(atom, Model),
    with_mutex(oro_write, create_model(Model)).

create_model(Model) :-
    oro_model(Model),
    !.
create_model(Model) :-
    model_key(Model, Key),
    (   Key == Model
    ->  true
    ;   oro_persist_note(model_key(Key, Model))
    ),
    forall(model_layer(Layer),
           ( model_graph_of(Key, Layer, Graph),
             assertz(model_graph(Graph, Model, Layer))
           )),
    debug(oro(store), 'Created model ~q', [Model]).

model_layer(profile(longterm)).
model_layer(profile(shortterm)).
model_layer(profile(episodic)).
model_layer(profile(timed)).
model_layer(mask).

%!  oro_model_alias(?Alias, ?Model) is nondet.
%
%   Alias names Model (`default` and the robot id name `myself`).

oro_model_alias(Alias, Model) :-
    model_alias(Alias, Model).

%!  oro_add_model_alias(+Alias, +Model) is det.
%
%   Make Alias a name of Model.

oro_add_model_alias(Alias, Model) :-
    must_be(atom, Alias),
    must_be(atom, Model),
    with_mutex(oro_write,
               (   model_alias(Alias, Model)
               ->  true
               ;   assertz(model_alias(Alias, Model))
               )).

%!  oro_resolve_model(+Name, -Model) is det.
%
%   Model is the model Name designates, directly or through an alias.
%   @error existence_error(agent, Name) if there is no such model.

oro_resolve_model(Name, Model) :-
    must_be(atom, Name),
    (   known_model(Name, Model0)
    ->  Model = Model0
    ;   catch(resolve_hook(Name), _, fail),
        known_model(Name, Model0)
    ->  Model = Model0
    ;   existence_error(agent, Name)
    ).

known_model(Name, Model) :-
    (   oro_model(Name)
    ->  Model = Name
    ;   model_alias(Name, Model)
    ).

%!  resolve_hook(+Name) is semidet.
%
%   Multifile hook called when no model is named Name, before giving
%   up: the agents module waits there for agent models still being
%   created.

:- multifile resolve_hook/1.

%!  oro_asserted(+Model, ?S, ?P, ?O) is nondet.
%
%   The triple S-P-O is asserted in Model: in one of its profile
%   graphs, or in the ontology layer and not removed from Model.
%   A triple stored in several graphs may be returned more than once.

oro_asserted(Model, S, P, O) :-
    rdf(S, P, O, Source),
    source_graph(Source, Graph),
    visible_in(Graph, Model, S, P, O).

%   Triples loaded from a file come with Graph:Line as their source.

source_graph(Graph:_, Graph) :-
    !.
source_graph(Graph, Graph).

visible_in(Graph, Model, _, _, _) :-
    model_graph(Graph, Model, profile(_)),
    !.
visible_in(Graph, Model, S, P, O) :-
    ontology_graph(Graph),
    oro_graph(Model, mask, Mask),
    \+ rdf(S, P, O, Mask).

%!  oro_asserted_count(+Model, -Count) is det.
%
%   The number of triples in the profile graphs of Model (what was
%   asserted through oro, not the ontology layer).

oro_asserted_count(Model, Count) :-
    aggregate_all(sum(N),
                  ( model_graph(Graph, Model, profile(_)),
                    rdf_graph_count(Graph, N)
                  ),
                  Count).

rdf_graph_count(Graph, N) :-
    (   rdf_graph(Graph)
    ->  rdf_statistics(triples_by_graph(Graph, N))
    ;   N = 0
    ).

%!  oro_store_write(+Action, :Goal) is semidet.
%
%   Run Goal as one atomic change: under the `oro_write` mutex, in one
%   rdf_transaction/2 whose id is oro(Action) (log(oro(Seq, Action))
%   when a database directory is attached, see oro_persist).  Writers
%   are serialised; readers are not blocked.  When it returns, the
%   change is durable if a database directory is attached.
%
%   Called inside Goal (by the same thread), it joins the outer change:
%   its Goal runs in a nested rdf_transaction/2 (rolled back alone if
%   it fails or raises), with no commit of its own; the outer one is
%   journaled, committed and seen by the watchers once.  A plugin
%   method calling oro_add/2 twice is thus one change.

oro_store_write(Action, Goal) :-
    (   nb_current(oro_store_writing, true)
    ->  rdf_transaction(Goal, oro(Action))
    ;   oro_store_read(with_mutex(oro_write, locked_write(Action, Goal)))
    ).

%   locked_write(+Action, :Goal): oro_store_write/2 holding the
%   `oro_write` mutex.  (The goals given to with_mutex/2 and
%   setup_call_cleanup/3 here and in store_write/2 are named
%   predicates: a meta-called conjunction or if-then-else is compiled
%   to a temporary clause on every call; the history of bench/RESULTS.md, "A request's
%   fixed cost".)

locked_write(Action, Goal) :-
    setup_call_cleanup(
        nb_setval(oro_store_writing, true),
        committed_write(Action, Goal),
        write_over).

committed_write(Action, Goal) :-
    store_write(Action, Goal),
    after_write,
    note_garbage.

write_over :-
    nb_setval(oro_store_writing, false),
    nb_setval(oro_store_schema_pending, false),
    nb_setval(oro_store_maybe_unused, []).

%   after_write: once a write is committed, drop the IRIs no triple
%   mentions any more from the name index, if it removed triples, and
%   renew the GC pin.

after_write :-
    (   nb_current(oro_store_maybe_unused, [_|_])
    ->  unindex_unused
    ;   true
    ),
    renew_gc_pin.

%   A schema change bumps the generation when it is made (before other
%   threads can see it) and again once the transaction is over,
%   committed or not (see oro_reason's schema cache).

store_write(Action, Goal) :-
    oro_schema_generation(Before),
    call_cleanup(oro_persist_transaction(Action, Goal),
                 schema_written(Before)).

schema_written(Before) :-
    (   oro_schema_generation(After),
        After =\= Before
    ->  schema_changed
    ;   true
    ).

%   schema_changed: the schema generation changes for good (not the
%   bump a schema triple makes inside its transaction): bump it and
%   tell the hooks.

schema_changed :-
    flag(oro_schema_generation, G, G+1),
    schema_hooks.

schema_hooks :-
    forall(schema_hook(changed), true).

%!  oro_store_assert(+Model, +Triples, +Profile) is det.
%
%   Assert each rdf(S,P,O) of Triples in Model with memory Profile
%   (lifespan(Seconds) goes in the graph of the `timed` profile).
%   Triples already visible are left alone; a masked ontology triple
%   is made visible again.  Must run inside oro_store_write/2.

oro_store_assert(Model, Triples, Profile0) :-
    oro_profile_layer(Profile0, Profile),
    oro_graph(Model, profile(Profile), Graph),
    oro_graph(Model, mask, Mask),
    maplist(assert_triple(Graph, Mask, Model, Profile), Triples).

%   A long-term triple is asserted unless it already lives forever (in
%   the long-term graph, or in the ontology layer and not masked); a
%   copy in a shorter profile's graph does not count.  A masked
%   ontology triple asserted long-term is unmasked: it lives forever
%   again.  A triple of a shorter profile goes in that profile's graph
%   (where its lifetime is counted) unless it is already there or lives
%   forever; a masked ontology triple stays masked, so that it goes
%   again when its lifetime is over.

assert_triple(Graph, Mask, Model, Profile, rdf(S, P, O)) :-
    note_schema_change(P, O),
    index_names(S, P, O),
    (   rdf(S, P, O)
    ->  assert_known(Graph, Mask, Model, Profile, S, P, O)
    ;   rdf_assert(S, P, O, Graph)      % in no graph: the usual new fact
    ).

assert_known(Graph, Mask, Model, Profile, S, P, O) :-
    (   Profile == longterm
    ->  (   rdf(S, P, O, Mask)
        ->  rdf_retractall(S, P, O, Mask)
        ;   true
        ),
        (   forever(Model, Mask, S, P, O)
        ->  true
        ;   rdf_assert(S, P, O, Graph)
        )
    ;   (   rdf(S, P, O, Graph)
        ;   forever(Model, Mask, S, P, O)
        )
    ->  true
    ;   rdf_assert(S, P, O, Graph)
    ).

forever(Model, Mask, S, P, O) :-
    oro_graph(Model, profile(longterm), Long),
    (   rdf(S, P, O, Long)
    ->  true
    ;   ontology_graph(Onto),
        rdf(S, P, O, Onto),
        \+ rdf(S, P, O, Mask)
    ->  true
    ).

%!  oro_store_forget(+Model, +Profile, +Triples) is det.
%
%   Remove Triples from the graph of Profile of Model only (their
%   lifetime in that profile is over); they stay visible if asserted
%   with another profile.  Must run inside oro_store_write/2.

oro_store_forget(Model, Profile, Triples) :-
    oro_graph(Model, profile(Profile), Graph),
    note_maybe_unused(Triples),
    forall(member(rdf(S, P, O), Triples),
           ( note_schema_change(P, O),
             rdf_retractall(S, P, O, Graph)
           )).

%!  oro_store_retract(+Model, +Triples) is det.
%
%   Remove each rdf(S,P,O) of Triples from Model: from its profile
%   graphs, and, if it comes from the ontology layer, by masking it.
%   Absent triples are ignored.  Must run inside oro_store_write/2.

oro_store_retract(Model, Triples) :-
    oro_graph(Model, mask, Mask),
    note_maybe_unused(Triples),
    maplist(retract_triple(Model, Mask), Triples).

retract_triple(Model, Mask, rdf(S, P, O)) :-
    note_schema_change(P, O),
    findall(Stored, oro_stored_term(S, P, O, Stored), Terms0),
    sort(Terms0, Terms),
    forall(member(Stored, Terms),
           retract_stored(Model, Mask, S, P, Stored)).

retract_stored(Model, Mask, S, P, O) :-
    forall(model_graph(Graph, Model, profile(_)),
           rdf_retractall(S, P, O, Graph)),
    (   ontology_graph(Onto),
        rdf(S, P, O, Onto),
        \+ rdf(S, P, O, Mask)
    ->  rdf_assert(S, P, O, Mask)
    ;   true
    ).

%!  oro_stored_term(+S, +P, +O, -Stored) is nondet.
%
%   Stored is how the object O of `S P O` may be spelled in the store:
%   O itself, and for a literal, the literal of the same datatype and
%   value that some triple `S P Stored` holds.  rdf_db keeps one term
%   for the literals of one datatype and value, spelled as the first
%   one asserted (`cup2 hasWeight 0.50` is stored as the `0.5` of
%   another triple), and a lookup with another spelling does not find
%   it.

oro_stored_term(_, _, O, O).
oro_stored_term(S, P, literal(Value), literal(Stored)) :-
    rdf(S, P, literal(eq(Value), Stored)),
    Stored \== Value,
    same_datatype(Value, Stored).

same_datatype(type(Type, _), type(Type, _)) :-
    !.
same_datatype(V1, V2) :-
    string_value(V1),
    string_value(V2).

string_value(Value) :-
    atom(Value),
    !.
string_value(type(Type, _)) :-
    rdf_equal(Type, xsd:string).

%!  oro_schema_generation(-Generation) is det.
%
%   A counter bumped by every change of a schema triple (see
%   oro_schema_triple/2), in any model or in the ontology layer.

oro_schema_generation(Generation) :-
    flag(oro_schema_generation, Generation, Generation).

note_schema_change(P, O) :-
    (   oro_schema_triple(P, O)
    ->  flag(oro_schema_generation, G, G+1),
        nb_setval(oro_store_schema_pending, true)
    ;   true
    ).

%!  oro_store_schema_pending is semidet.
%
%   True in the thread of a write (oro_store_write/2) that has changed
%   a schema triple.  Until the write is over, that thread sees a schema
%   other threads do not, under the same schema generation: the shared
%   tables of that generation (oro_reason) are not for it.

oro_store_schema_pending :-
    nb_current(oro_store_schema_pending, true).

%!  oro_schema_triple(+P, +O) is semidet.
%
%   A triple with predicate P and object O changes the schema: the
%   class or property hierarchy, property characteristics, restrictions
%   or owl:sameAs.

:- rdf_meta
    oro_schema_triple(r, o),
    schema_predicate(r),
    oro_schema_class(r).

oro_schema_triple(P, _) :-
    schema_predicate(P),
    !.
oro_schema_triple(rdf:type, O) :-
    oro_schema_class(O).

schema_predicate(rdfs:subClassOf).
schema_predicate(rdfs:subPropertyOf).
schema_predicate(rdfs:domain).
schema_predicate(rdfs:range).
schema_predicate(owl:inverseOf).
schema_predicate(owl:equivalentClass).
schema_predicate(owl:equivalentProperty).
schema_predicate(owl:sameAs).
schema_predicate(owl:disjointWith).
schema_predicate(owl:complementOf).
schema_predicate(owl:propertyChainAxiom).
schema_predicate(owl:onProperty).
schema_predicate(owl:hasValue).
schema_predicate(owl:someValuesFrom).
schema_predicate(owl:allValuesFrom).
schema_predicate(owl:intersectionOf).
schema_predicate(owl:unionOf).
schema_predicate(owl:propertyDisjointWith).
schema_predicate(rdf:first).
schema_predicate(rdf:rest).

%!  oro_schema_class(?Class) is nondet.
%
%   Class is a meta-class whose instances define the schema: classes,
%   properties and their characteristics, restrictions.

oro_schema_class(owl:'Class').
oro_schema_class(rdfs:'Class').
oro_schema_class(rdf:'Property').
oro_schema_class(owl:'ObjectProperty').
oro_schema_class(owl:'DatatypeProperty').
oro_schema_class(owl:'AnnotationProperty').
oro_schema_class(owl:'TransitiveProperty').
oro_schema_class(owl:'SymmetricProperty').
oro_schema_class(owl:'FunctionalProperty').
oro_schema_class(owl:'InverseFunctionalProperty').
oro_schema_class(owl:'AsymmetricProperty').
oro_schema_class(owl:'ReflexiveProperty').
oro_schema_class(owl:'IrreflexiveProperty').
oro_schema_class(owl:'Restriction').

%!  oro_load_ontology(+File) is det.
%!  oro_load_ontology(+File, +Options) is det.
%
%   Load File (RDF/XML `.owl`/`.rdf`, Turtle `.ttl`, N-Triples `.nt`)
%   into a graph of its own in the ontology layer.  Options:
%
%     - silent(+Bool): if `false`, print the triples loaded so far
%       every `load_progress_interval` seconds while loading (on a
%       terminal, see the setting `load_progress`), and a one-line
%       summary once loaded (message oro(ontology_loaded(File, Triples,
%       Seconds))).  Default `true`: nothing is printed.

oro_load_ontology(File) :-
    oro_load_ontology(File, []).

oro_load_ontology(File, Options) :-
    must_be(atom, File),
    must_be(list, Options),
    option(silent(Silent), Options, true),
    must_be(boolean, Silent),
    absolute_file_name(File, Path, [access(read)]),
    file_format(Path, Format),
    get_time(Start),
    with_mutex(oro_write,
               load_reported(Path, Silent,
                             load_ontology(Path, Format, Graph))),
    (   Silent == true
    ->  true
    ;   rdf_graph_property(Graph, triples(Triples)),
        get_time(End),
        Seconds is End - Start,
        print_message(informational,
                      oro(ontology_loaded(Path, Triples, Seconds)))
    ).

load_ontology(Path, Format, Graph) :-
    aggregate_all(count, ontology_graph(_), N0),
    N is N0 + 1,
    oro_shared_graph(ontology(N), Graph),
    oro_persist_exclude(Graph),
    uri_file_name(URL, Path),               % relative IRIs: the file's,
    rdf_load(Path, [graph(Graph), base_uri(URL),   % not the graph's
                    format(Format), silent(true)]),
    assertz(ontology_graph(Graph)),
    index_graph_names(Graph),
    schema_changed.

:- setting(load_progress, oneof([tty, true, false]), tty,
           'When a load that is not silent reports its progress: when \c
           stderr is a terminal (tty), always (true) or never (false)').
:- setting(load_progress_interval, number, 1,
           'Seconds between two progress reports of an ontology load').

%   load_reported(+Path, +Silent, :Load): run Load; unless Silent, a
%   thread reports the triples loaded so far every
%   load_progress_interval seconds meanwhile (then indexing the names
%   of the graph: the count no longer grows, the seconds do).  rdf_statistics/1 counts
%   the triples of the load's transaction before it commits, and
%   oro_write is held: the difference is what the load has added.

load_reported(Path, Silent, Load) :-
    (   Silent == false,
        load_progress
    ->  rdf_statistics(triples(Triples0)),
        get_time(Start),
        setting(load_progress_interval, Interval),
        message_queue_create(Queue),
        setup_call_cleanup(
            thread_create(report_progress(Queue, Interval,
                                          progress(Path, Triples0, Start)),
                          Reporter, []),
            Load,
            ( thread_send_message(Queue, done),
              thread_join(Reporter, _),
              message_queue_destroy(Queue)
            ))
    ;   call(Load)
    ).

load_progress :-
    setting(load_progress, When),
    (   When == tty
    ->  stream_property(user_error, tty(true))
    ;   When == true
    ).

report_progress(Queue, Interval, Progress) :-
    (   thread_get_message(Queue, done, [timeout(Interval)])
    ->  true
    ;   Progress = progress(Path, Triples0, Start),
        rdf_statistics(triples(Triples1)),
        get_time(Now),
        Triples is max(0, Triples1 - Triples0),
        Seconds is Now - Start,
        print_message(informational,
                      oro(ontology_loading(Path, Triples, Seconds))),
        report_progress(Queue, Interval, Progress)
    ).

file_format(Path, Format) :-
    file_name_extension(_, Ext0, Path),
    downcase_atom(Ext0, Ext),
    (   extension_format(Ext, Format)
    ->  true
    ;   domain_error(ontology_file, Path)
    ).

extension_format(owl, xml).
extension_format(rdf, xml).
extension_format(xml, xml).
extension_format(ttl, turtle).
extension_format(nt, ntriples).

%!  oro_wipe_models is det.
%
%   Remove every model but the robot's and every alias of them, with
%   all their triples, and empty the robot's model; the ontology layer
%   stays.  Used by reset.  The robot's model and its aliases stay
%   known throughout, so that a request naming it while another resets
%   the store is not told that there is no such model.

oro_wipe_models :-
    with_mutex(oro_write,
               ( forall(model_graph(Graph, _, _), rdf_unload_graph(Graph)),
                 forall(( model_graph(Graph, Model, Layer),
                          Model \== myself
                        ),
                        retract(model_graph(Graph, Model, Layer))),
                 retractall(name_of(_, _)),
                 forall(ontology_graph(Onto), index_graph_names(Onto)),
                 forall(( model_alias(Alias, Model),
                          Model \== myself
                        ),
                        retract(model_alias(Alias, Model))),
                 schema_changed
               )).

%   Presized hash tables double rdf_assert/4's speed on a growing store
%   (1.5 us instead of 3.4 us a triple, bench/bench_reasoner.pl); 2^18 buckets cost
%   about 20 MB for the nine indexes.

presize_indexes :-
    forall(member(Index, [s, p, o, sp, po, spo, g, sg, pg]),
           rdf_set(hash(Index, size, 262144))).

%!  oro_store_reset is det.
%
%   Empty the whole store: every model, alias and ontology graph.  The
%   graphs are unloaded rather than the database reset (rdf_reset_db/0),
%   which would free the snapshots event watchers may still hold.

oro_store_reset :-
    with_mutex(oro_write,
               ( forall(rdf_graph(Graph), rdf_unload_graph(Graph)),
                 presize_indexes,
                 renew_gc_pin,
                 retractall(name_of(_, _)),
                 retractall(model_graph(_, _, _)),
                 retractall(model_alias(_, _)),
                 retractall(ontology_graph(_)),
                 schema_changed
               )).

		 /*******************************
		 *          DURABILITY          *
		 *******************************/

%!  oro_store_attach(+Directory) is det.
%
%   Journal the models in Directory (see oro_persist), restoring the
%   models it holds first: each graph found there becomes the graph of
%   its model again.  The ontology layer is not journaled.

oro_store_attach(Dir) :-
    must_be(atom, Dir),
    with_mutex(oro_write,
               ( oro_persist_attach(Dir),
                 forall(ontology_graph(Graph), oro_persist_exclude(Graph)),
                 forall(digest_named(Key, Model),
                        oro_persist_note(model_key(Key, Model))),
                 oro_persist_records(Records),
                 forall(( rdf_graph(Graph),
                          model_graph_name(Graph, Key),
                          key_model(Records, Key, Model)
                        ),
                        ( create_model(Model),
                          index_graph_names(Graph)
                        )),
                 schema_changed
               )).

%   model_graph_name(+Graph, -Key): Graph is named by oro_graph/3
%   (the inverse of graph_name/3 for a model's layers).

model_graph_name(Graph, Key) :-
    atom_concat('oro:', Rest, Graph),
    sub_atom(Rest, Before, _, After, '#'),
    sub_atom(Rest, _, After, 0, LayerName),
    \+ sub_atom(LayerName, _, _, _, '#'),
    layer_name(Layer, LayerName),
    model_layer(Layer),
    !,
    sub_atom(Rest, 0, Before, _, Key).

%   key_model(+Records, +Key, -Model): the model named Key in its
%   graphs' names (see model_key/2).

key_model(Records, Key, Model) :-
    (   memberchk(model_key(Key, Model0), Records)
    ->  Model = Model0
    ;   Model = Key
    ).

%   digest_named(?Key, ?Model): Model exists and is named by the
%   digest Key in its graphs' names.

digest_named(Key, Model) :-
    model_graph(_, Model, profile(longterm)),
    model_key(Model, Key),
    Key \== Model.

%   The names of the models named by a digest are the records a
%   compacted commit log keeps (oro_persist).

:- multifile oro_persist:live_records/1.

oro_persist:live_records(Records) :-
    findall(model_key(Key, Model), digest_named(Key, Model), Records).

%!  oro_store_detach is det.
%
%   Stop journaling (nothing happens if no directory is attached).  The
%   store keeps its content.

oro_store_detach :-
    with_mutex(oro_write, oro_persist_detach).

%!  oro_scratch_graph(+Graph) is det.
%
%   Graph is a temporary graph (not journaled, not part of any model).

oro_scratch_graph(Graph) :-
    oro_persist_exclude(Graph).


		 /*******************************
		 *          NAME INDEX          *
		 *******************************/

%!  oro_named(+LowerLocalName, -IRI) is nondet.
%
%   IRI has LowerLocalName as its local name (see oro_local_name/2),
%   ignoring case.  The index holds every IRI the store was given
%   (subject, predicate or object), models and ontology layer; it may
%   hold IRIs whose triples are gone since: check with the model.
%
%   rdf_db has no index on local names, and scanning its resources
%   costs 30 ms at 10k triples, 350 ms at 1M (bench/bench_full.pl,
%   lookup).  The index is kept by the write path itself (a hash
%   lookup per IRI, where an rdf_monitor/2 callback would add a call
%   from C per triple), and by a scan of what rdf_load/2 and a
%   restored database bring.  An IRI whose last triple a write removed leaves the index
%   once the write is committed, so names that come and go do not pile
%   up (a write rolled back keeps its IRIs).

oro_named(Lower, IRI) :-
    name_of(IRI, Lower).                % JIT-indexed on either argument

index_names(S, P, O) :-
    index_name(S),
    index_name(P),
    (   atom(O)
    ->  index_name(O)
    ;   true
    ).

index_name(R) :-
    (   name_of(R, _)
    ->  true
    ;   rdf_is_bnode(R)
    ->  true
    ;   oro_local_name(R, Local),
        downcase_atom(Local, Lower),
        assertz(name_of(R, Lower))
    ).

%   note_maybe_unused(+Triples): this write removes Triples, whose
%   subjects and objects may be mentioned by no triple once it is done.
%   They are kept, unsorted, in the writing thread's global variable
%   oro_store_maybe_unused (see "Writes leave no clause behind"), one
%   update per call.

note_maybe_unused(Triples) :-
    findall(R, ( member(rdf(S, _, O), Triples),
                 (   R = S
                 ;   atom(O),
                     R = O
                 )
               ),
            New),
    (   nb_current(oro_store_maybe_unused, Old)
    ->  true
    ;   Old = []
    ),
    append(New, Old, All),
    nb_setval(oro_store_maybe_unused, All).

%   unindex_unused: after a committed write, drop the IRIs no triple
%   mentions any more.

unindex_unused :-
    nb_getval(oro_store_maybe_unused, Rs0),
    nb_setval(oro_store_maybe_unused, []),
    sort(Rs0, Rs),
    forall(( member(R, Rs),
             \+ rdf(R, _, _),
             \+ rdf(_, _, R),
             \+ rdf_current_predicate(R)
           ),
           retractall(name_of(R, _))).

index_graph_names(Graph) :-
    forall(rdf(S, P, O, Graph),
           index_names(S, P, O)).


		 /*******************************
		 *           REBUILD            *
		 *******************************/

/* rdf_db (SWI-Prolog 9.0.4) keeps every IRI it has ever been given in
its resource table, with the atom, until rdf_reset_db/0: a robot naming
new short-lived objects all day grows without bound, though no triple
mentions them any more.  A *rebuild* gives that memory back: the store
is emptied with the reset and filled again with the same triples.

A reset must not run while another thread reads rdf_db: it crashes the
process.  Readers therefore pass a *gate*: oro_store_read/1 counts them
in and out, and a rebuild closes the gate, waits for the readers inside
to leave, rebuilds, and opens it again.  Every write goes through the
gate (oro_store_write/2), and so does every request of the server.  The
watcher thread reads only snapshots of committed changes: a rebuild
waits until it has processed them all (rebuild_hook(blocked(_))).
What it reads outside a change (schema tables compiled ahead) goes
through the gate with oro_store_try_read/1, which does not wait: it is
left for later while a rebuild is due.

Rebuilds are off unless the setting rebuild_garbage is set (the server
sets it): a program that reads the store from several threads outside
oro_store_read/1 must leave it off. */

:- setting(rebuild_garbage, nonneg, 0,
           'Resources rdf_db may hold beyond those it held after the last \c
           rebuild (or twice as many, if more) before the store is rebuilt \c
           to give their memory back (0: never rebuild)').
:- setting(rebuild_wait, number, 2,
           'Seconds a rebuild waits for the readers and watchers in progress \c
           before it gives up, to try again later').

%!  rebuild_hook(+Phase) is semidet.
%
%   Multifile hook called by a rebuild, with no reader in the gate
%   (and, but for the first `blocked`, the `oro_write` mutex held).
%   Phase is
%
%     - blocked(+Deadline): succeed if the module still refers to
%       rdf_db (snapshots) at time stamp Deadline: the rebuild gives
%       up;
%     - suspend: stop the rdf_monitor/2 callbacks, which must not see
%       the store emptied and filled again;
%     - resume: start them again.  What was derived from rdf_db
%       generations (rdf_generation/1, reset to 0) is forgotten.

:- multifile rebuild_hook/1.

%!  schema_hook(+Event) is semidet.
%
%   Multifile hook called with Event `changed` once the schema
%   generation (oro_schema_generation/1) has changed for good: after a
%   write that changed a schema triple (committed or rolled back), an
%   ontology loaded, the models wiped, the store reset, a database
%   attached or a store rebuilt (once readers may enter again).  The
%   bump a schema triple makes inside its transaction does not call
%   it.  Called by the thread that made the change, which may hold the
%   `oro_write` mutex: a hook must be quick and must not wait for
%   another thread.  The events module uses it to have the schema
%   tables compiled ahead.

:- multifile schema_hook/1.

%!  oro_store_read(:Goal) is semidet.
%
%   Run Goal once, reading (or writing) the store, with no rebuild in
%   progress: a rebuild waits until Goal is over, and Goal waits until a
%   rebuild is over.  Calls nest.  If a rebuild is due when the
%   outermost call is over, the calling thread runs it.

oro_store_read(Goal) :-
    must_be(callable, Goal),
    (   nb_current(oro_store_reader, true)
    ->  once(Goal)
    ;   setup_call_cleanup(enter_gate, once(Goal), leave_gate),
        rebuild_if_due
    ).

%!  oro_store_try_read(:Goal) is semidet.
%
%   As oro_store_read/1, but if a rebuild is in progress or waiting
%   for the readers, fail at once instead of waiting; and never run a
%   rebuild.  The calling thread is counted in even if it passes a
%   closed gate otherwise (oro_store_gate_exempt/0): for work in the
%   background that reads rdf_db and can be left for later, such as the
%   watcher thread compiling schema tables ahead.

oro_store_try_read(Goal) :-
    must_be(callable, Goal),
    (   nb_current(oro_store_reader, true)
    ->  once(Goal)
    ;   setup_call_cleanup(gate_count(1, Rebuilding),
                           open_gate_goal(Rebuilding, Goal),
                           leave_gate)
    ).

open_gate_goal(0, Goal) :-
    nb_setval(oro_store_reader, true),
    once(Goal).

%   The reader counts itself in and looks for a rebuild; the rebuild
%   marks itself, then counts the readers: one of them sees the other.

enter_gate :-
    gate_count(1, Rebuilding),
    (   (   Rebuilding == 0
        ;   nb_current(oro_store_gate_exempt, true)
        )
    ->  nb_setval(oro_store_reader, true)
    ;   gate_count(-1, _),
        with_mutex(oro_store_rebuild, true),    % held by the rebuild
        enter_gate
    ).

leave_gate :-
    nb_setval(oro_store_reader, false),
    gate_count(-1, _).

%   gate_count(+Delta, -Rebuilding): add Delta to the count of readers
%   in the gate and read the rebuild's mark, under the mutex
%   oro_store_gate, which the rebuild holds to set its mark
%   (set_rebuilding/1): a reader and a rebuild are ordered by it.
%   Called only by the setup and cleanup of oro_store_read/1 and
%   oro_store_try_read/1, where signals wait, so the mutex is always
%   unlocked.  (Not flag/3, which meta-calls update_flag/3 under a
%   global mutex on every update.)

gate_count(Delta, Rebuilding) :-
    mutex_lock(oro_store_gate),
    get_flag(oro_store_readers, N0),
    N is N0 + Delta,
    set_flag(oro_store_readers, N),
    get_flag(oro_store_rebuilding, Rebuilding),
    mutex_unlock(oro_store_gate).

set_rebuilding(Mark) :-
    with_mutex(oro_store_gate, set_flag(oro_store_rebuilding, Mark)).

rebuild_if_due :-
    (   flag(oro_store_rebuild_due, 1, 1),
        \+ nb_current(oro_store_gate_exempt, true)
    ->  catch(rebuild_due, E, print_message(warning, E))
    ;   true
    ).

rebuild_due :-
    (   oro_store_rebuild
    ->  true
    ;   rdf_statistics(resources(R)),           % try again a bit later
        setting(rebuild_garbage, Garbage),
        Retry is R + max(1, Garbage // 10),
        flag(oro_store_rebuild_retry, _, Retry),
        flag(oro_store_rebuild_due, _, 0)
    ).

%   note_garbage: after a committed write, see whether rdf_db holds
%   enough resources beyond the live ones for a rebuild to be due.  The
%   live ones are counted after each rebuild (0: not yet counted).

note_garbage :-
    setting(rebuild_garbage, Garbage),
    (   Garbage =:= 0
    ->  true
    ;   rdf_statistics(resources(R)),
        flag(oro_store_rebuild_live, Live, Live),
        flag(oro_store_rebuild_retry, Retry, Retry),
        (   Live =:= 0
        ->  rebuilt(R)
        ;   R > Live + max(Garbage, Live),
            R > Retry
        ->  flag(oro_store_rebuild_due, _, 1)
        ;   true
        )
    ).

rebuilt(Live) :-
    flag(oro_store_rebuild_live, _, Live),
    flag(oro_store_rebuild_retry, _, 0),
    flag(oro_store_rebuild_due, _, 0).

%!  oro_store_gate_exempt is det.
%
%   The calling thread passes a closed gate (oro_store_read/1), and
%   never runs a rebuild itself: for the watcher thread, which a
%   rebuild waits for (rebuild_hook/1, `blocked`) before it takes the
%   `oro_write` mutex.

oro_store_gate_exempt :-
    nb_setval(oro_store_gate_exempt, true).

%!  oro_store_rebuild is semidet.
%
%   Rebuild the store now: empty rdf_db (rdf_reset_db/0) and fill it
%   again with the same graphs and triples, so that it gives back the
%   memory of the IRIs no triple mentions any more.  Models, watchers,
%   deadlines and the journal are not affected; nothing is seen by the
%   watchers.  Readers wait meanwhile (oro_store_read/1).  With a
%   database directory, the models are reloaded from it (after the
%   journals are flushed) and the ontology layer is copied.
%
%   Fails, changing nothing, if the readers inside oro_store_read/1 or
%   the watcher thread are not done within the setting rebuild_wait.
%
%   @error permission_error(rebuild, oro_store, inside_reader) if
%   called inside oro_store_read/1 or oro_store_write/2.

oro_store_rebuild :-
    (   nb_current(oro_store_reader, true)
    ->  permission_error(rebuild, oro_store, inside_reader)
    ;   true
    ),
    setting(rebuild_wait, Wait),
    get_time(Now),
    Deadline is Now + Wait,
    with_mutex(oro_store_rebuild,
               setup_call_cleanup(
                   set_rebuilding(1),
                   ( readers_gone(Deadline),
                     \+ rebuild_hook(blocked(Deadline)),
                     with_mutex(oro_write, rebuild_quiet(Deadline))
                   ),
                   set_rebuilding(0))),
    schema_hooks.                       % once readers may enter again

readers_gone(Deadline) :-
    get_flag(oro_store_readers, N),
    (   N =:= 0
    ->  true
    ;   get_time(Now),
        Now < Deadline,
        sleep(0.001),
        readers_gone(Deadline)
    ).

%   Once the readers are gone, the hooks let go of rdf_db first
%   without the `oro_write` mutex (the watcher thread may still write),
%   then again with it (nothing can write any more).

rebuild_quiet(Deadline) :-
    \+ rebuild_hook(blocked(Deadline)),
    rdf_statistics(resources(Before)),
    statistics(cputime, T0),
    forall(rebuild_hook(suspend), true),
    call_cleanup(refill_store,
                 forall(rebuild_hook(resume), true)),
    flag(oro_schema_generation, G, G+1),
    flag(oro_store_rebuilds, N, N+1),
    rdf_statistics(resources(After)),
    rebuilt(After),
    statistics(cputime, T1),
    T is T1 - T0,
    debug(oro(store), 'Rebuilt the store: ~D resources before, ~D after \c
                       (~3f s)', [Before, After, T]).

%   refill_store: empty rdf_db and fill it again.  Triples keep their
%   source (Graph:Line); the gensym counter of blank nodes is kept
%   (rdf_reset_db/0 would restart it, and a new blank node could take
%   the name of an old one).

refill_store :-
    (   oro_persist_directory(Dir)
    ->  findall(G, ( rdf_graph(G), \+ model_graph(G, _, _) ), Copied),
        copy_graphs(Copied, Copies),
        oro_persist_detach,
        reset_rdf_db,
        restore_graphs(Copies),
        oro_persist_attach(Dir),
        maplist(oro_persist_exclude, Copied)
    ;   findall(G, rdf_graph(G), Graphs),
        copy_graphs(Graphs, Copies),
        reset_rdf_db,
        restore_graphs(Copies)
    ).

copy_graphs(Graphs, Copies) :-
    findall(G-Triples,
            ( member(G, Graphs),
              findall(rdf(S, P, O, Source),
                      ( rdf(S, P, O, G:Line),
                        (   var(Line)
                        ->  Source = G
                        ;   Source = G:Line
                        )
                      ),
                      Triples)
            ),
            Copies).

restore_graphs(Copies) :-
    forall(member(G-Triples, Copies),
           ( rdf_create_graph(G),
             forall(member(rdf(S, P, O, Source), Triples),
                    rdf_assert(S, P, O, Source))
           )).

reset_rdf_db :-
    release_gc_pin,
    rdf_db:rdf_reset_db_,           % rdf_reset_db/0 without reset_gensym/1
    renew_gc_pin,
    presize_indexes.

%   renew_gc_pin: replace the GC pin (see the module's documentation) by
%   a snapshot of now, taken before the old one is deleted, so that one
%   is alive at every moment.  Called with the `oro_write` mutex held
%   (or while the module loads).  A pin erased meanwhile by
%   rdf_reset_db/0, called outside this module, is simply dropped.

renew_gc_pin :-
    rdf_snapshot(Pin),
    release_gc_pin,
    thread_send_message(oro_gc_pin, gc_pin(Pin)).

release_gc_pin :-
    oro_drain_queue(oro_gc_pin, Pins),
    forall(member(gc_pin(Old), Pins),
           catch(rdf_delete_snapshot(Old), error(existence_error(_, _), _),
                 true)).

%!  oro_drain_queue(+Queue, -Messages) is det.
%
%   Take every message of Queue, oldest first, without waiting.  Only
%   for a queue that no other thread reads meanwhile (its owner's, or
%   one read under a mutex), so that a message peeked at is still there
%   to take.  (It peeks rather than calling
%   thread_get_message/3 with timeout(0), which was seen to spin for
%   ever in SWI-Prolog 9.0.4, while this module loads.)

oro_drain_queue(Queue, Messages) :-
    (   thread_peek_message(Queue, Message)
    ->  thread_get_message(Queue, Message),
        Messages = [Message|Rest],
        oro_drain_queue(Queue, Rest)
    ;   Messages = []
    ).

%   The pin is the one message gc_pin(Snapshot) of the queue
%   oro_gc_pin, which only the holder of the `oro_write` mutex changes:
%   a message queue, unlike a fact, leaves nothing for the clause
%   garbage collector when the pin is replaced.

:- initialization(( gc_pin_queue,
                    with_mutex(oro_write, renew_gc_pin)
                  )).

gc_pin_queue :-
    (   catch(message_queue_property(_, alias(oro_gc_pin)), _, fail)
    ->  true                            % the module was loaded again
    ;   message_queue_create(_, [alias(oro_gc_pin)])
    ).
