:- module(oro_kbapi_methods,
          [ kb_connection_open/3,       % +Out, +Mutex, -Context
            kb_connection_closed/1,     % +Context
            kb_dispatch/5,              % +Context, +Method, +Args, +KWArgs, -Reply
            kb_error_reply/2,           % +Error, -Reply
            kb_method/2                 % ?Name, ?Params
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(debug)).
:- use_module(library(settings)).
:- use_module(library(http/json)).
:- use_module(library(oro)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store),
              [ oro_model/1,
                oro_create_model/1,
                oro_shared_graph/2,
                oro_scratch_graph/1
              ]).
:- use_module(library(oro/server/oro_protocol)).
:- use_module(library(oro/oro_errors)).
:- use_module(library(oro/server/oro_methods_explain)).
:- use_module(library(oro/kbapi/oro_kbapi_events)).

/** <module> The KB-API methods

The methods of knowledge_core's socket API (its `doc/api.md`), with
minimalkb's forms where they differ, and oro's extras, on oro's
library.  kb_method/2 is the table: each method has named parameters
with defaults, filled from the positional arguments then the keyword
arguments, as Python calls them.

Models: `models` is a list of model names (or one name).  Missing,
`null`, `[]` or `""` is the robot's model (`myself`, also `default`);
a list holding `all` is every model; any other name is an agent's
model, created empty if it does not exist (knowledge_core creates
models on first use).  A change applies to each model, a query answers
the union over them.

Lifespans: `lifespan` (seconds, 0 for ever) becomes oro's memory
lifespan(Seconds) (oro_memory); at the default time base one unit is a
second.
*/

:- setting(event_queue, positive_integer, 10000,
           'Events a KB-API connection may have waiting to be written').

%!  kb_method(?Name, ?Params) is nondet.
%
%   The KB-API methods: Name and its parameters, each Name or
%   Name=Default (optional).

kb_method(hello, []).
kb_method(version, []).
kb_method(methods, []).
kb_method(about, [term, models=null]).
kb_method(lookup, [term, models=null]).
kb_method(label, [term, models=null]).
kb_method(details, [resource, models=null]).
kb_method(classesof, [term, direct=false, models=null]).
kb_method(exist, [stmts, models=null]).
kb_method(find, [vars, patterns=null, constraints=null, models=null]).
kb_method(revise, [stmts, policy]).
kb_method(add, [stmts, models=null, lifespan=0]).
kb_method(update, [stmts, models=null, lifespan=0]).
kb_method(retract, [stmts, models=null]).
kb_method(remove, [stmts, models=null]).
kb_method(subscribe, [patterns, one_shot=false, models=null]).
kb_method(sparql, [query, model=null]).
kb_method(load, [filename, models=null]).
kb_method(save, [path=".", basename="kb", models=null]).
kb_method(clear, []).
kb_method(reset, []).
kb_method(close, []).
% oro's extras
kb_method(safe_add, [stmts, models=null, lifespan=0]).
kb_method(check_consistency, [models=null]).
kb_method(explain, [stmts, models=null]).
kb_method(similarities, [term1, term2, models=null]).
kb_method(differences, [term1, term2, models=null]).
kb_method(discriminate, [terms, models=null]).

		 /*******************************
		 *          CONNECTION          *
		 *******************************/

%!  kb_connection_open(+Out, +Mutex, -Context) is det.
%
%   The context of a new connection writing to Out under Mutex.  Its
%   event queue and the thread writing its events are made on its
%   first subscription.

kb_connection_open(Out, Mutex, Context) :-
    Context = kb_connection{out:Out, mutex:Mutex, events:slot(none)}.

%!  kb_connection_closed(+Context) is det.
%
%   Release the subscriptions and the event thread of a connection.

kb_connection_closed(Context) :-
    Context.events = slot(Events),
    (   Events = events(Queue, Thread)
    ->  kb_client_gone(Queue),
        (   catch(thread_send_message(Queue, stop, [timeout(0)]), _, fail)
        ->  true
        ;   catch(thread_signal(Thread, throw(kb_events_stop)), _, true)
        ),
        (   thread_self(Thread)
        ->  true
        ;   catch(thread_join(Thread, _), _, true)
        ),
        catch(message_queue_destroy(Queue), _, true)
    ;   true
    ).

client_queue(Context, Queue) :-
    Slot = Context.events,
    (   Slot = slot(events(Queue0, _))
    ->  Queue = Queue0
    ;   setting(event_queue, Max),
        message_queue_create(Queue, [max_size(Max)]),
        thread_create(catch(deliver_events(Queue, Context.out, Context.mutex),
                            kb_events_stop, true),
                      Thread, []),
        nb_setarg(1, Slot, events(Queue, Thread))
    ).

deliver_events(Queue, Out, Mutex) :-
    thread_get_message(Queue, Message),
    (   Message = event(Id, Rows)
    ->  with_output_to(string(JSON),
                       json_write_dict(current_output, Rows, [width(0)])),
        catch(with_mutex(Mutex, oro_write_event(Out, Id, raw(JSON))),
              E, debug(oro(kbapi), 'Event not written: ~q', [E])),
        deliver_events(Queue, Out, Mutex)
    ;   true                                % stop
    ).

		 /*******************************
		 *           DISPATCH           *
		 *******************************/

%!  kb_dispatch(+Context, +Method, +Args, +KWArgs, -Reply) is det.
%
%   Run Method (a string) with the positional JSON Args and the dict
%   KWArgs of keyword arguments.  Reply is ok(JSON), ok(void) or
%   error(Message).

kb_dispatch(Context, Method, Args, KWArgs, Reply) :-
    (   catch(dispatch(Context, Method, Args, KWArgs, Value), Error, true)
    ->  (   var(Error)
        ->  Reply = ok(Value)
        ;   kb_error_reply(Error, Reply)
        )
    ;   kb_error_reply(error(oro_method(failed), _), Reply)
    ).

%!  kb_error_reply(+Error, -Reply) is det.
%
%   The reply error(Message) for an exception: the message of the ORO
%   error table (oro_errors), after the short name of its exception.

kb_error_reply(error(domain_error(kb_json_parameter, Line), _),
               error(Message)) :-
    !,
    format(string(Message), "IllegalArgumentException: a parameter is \c
                             not valid JSON: ~w", [Line]).
kb_error_reply(error(kb(Format, Args), _), error(Message)) :-
    !,
    format(string(Message0), Format, Args),
    string_concat("IllegalArgumentException: ", Message0, Message).
kb_error_reply(Error, error(Message)) :-
    oro_error_response(Error, Name, Text),
    atomic_list_concat(Parts, '.', Name),
    last(Parts, Short),
    format(string(Message), "~w: ~w", [Short, Text]).

dispatch(Context, Method0, Args, KWArgs, Value) :-
    atom_string(Method, Method0),
    (   kb_method(Method, Params)
    ->  true
    ;   kb_error("unknown method '~w' (see methods())", [Method])
    ),
    call_args(Method, Args, Params, KWArgs, Values),
    method(Method, Context, Values, Value).

%   call_args(+Method, +Args, +Params, +KWArgs, -Values): the value of
%   each parameter, in order; the first argument may be passed
%   positionally, the others too or by name.

call_args(Method, Args, Params, KWArgs, Values) :-
    length(Args, NArgs),
    length(Params, NParams),
    (   NArgs =< NParams
    ->  true
    ;   method_minimalkb_form(Method, NArgs)
    ->  true
    ;   kb_error("~w() takes at most ~D arguments (~D given)",
                 [Method, NParams, NArgs])
    ),
    dict_pairs(KWArgs, _, KWPairs),
    forall(member(K-_, KWPairs),
           (   ( memberchk(K, Params) ; memberchk(K=_, Params) )
           ->  true
           ;   kb_error("~w() got an unexpected keyword argument '~w'",
                        [Method, K])
           )),
    (   method_minimalkb_form(Method, NArgs)
    ->  Values = Args
    ;   fill(Params, Args, KWArgs, Method, Values)
    ).

method_minimalkb_form(subscribe, N) :-
    between(4, 5, N).

fill([], _, _, _, []).
fill([Param|Params], Args0, KWArgs, Method, [Value|Values]) :-
    param_name(Param, Name, Default),
    (   Args0 = [Value|Args]
    ->  (   get_dict(Name, KWArgs, _)
        ->  kb_error("~w() got multiple values for argument '~w'",
                     [Method, Name])
        ;   true
        )
    ;   Args = [],
        (   get_dict(Name, KWArgs, Value0)
        ->  Value = Value0
        ;   Default \== '$required'
        ->  Value = Default
        ;   kb_error("~w() missing required argument: '~w'", [Method, Name])
        )
    ),
    fill(Params, Args, KWArgs, Method, Values).

param_name(Name=Default, Name, Default) :-
    !.
param_name(Name, Name, '$required').

kb_error(Format, Args) :-
    throw(error(kb(Format, Args), _)).

		 /*******************************
		 *            METHODS           *
		 *******************************/

%   method(+Name, +Context, +Values, -Reply): Reply is a JSON term or
%   `void`.

method(hello, _, [], Text) :-
    kb_version(Version),
    format(string(Text), "oro-server ~w (KB-API)", [Version]).
method(version, _, [], Version) :-
    kb_version(Version).
method(methods, _, [], Names) :-
    findall(Text,
            ( kb_method(Name, Params),              % close too: pykb's
              maplist(param_text, Params, Texts),   % close() calls it
              atomic_list_concat(Texts, ', ', Inner),
              format(string(Text), "~w(~w)", [Name, Inner])
            ),
            Names).
method(about, _, [Term, Models0], Triples) :-
    models(Models0, Models),
    term_name(Term, Resource),
    findall([S, P, O],
            ( member(Model, Models),
              about(Model, Resource, S0, P0, O0),
              maplist(kb_json_term, [S0, P0, O0], [S, P, O])
            ),
            Triples0),
    sort(Triples0, Triples).
method(lookup, _, [Term, Models0], Pairs) :-
    models(Models0, Models),
    must_be(text, Term),
    findall(Pair, ( member(Model, Models),
                    lookup(Model, Term, Pair)
                  ), Pairs0),
    sort(Pairs0, Pairs).
method(label, _, [Term, Models0], Labels) :-
    models(Models0, Models),
    term_name(Term, Resource),
    labels(Models, Resource, Labels).
method(details, _, [Term, Models0], Details) :-
    models(Models0, [Model|_]),
    details(Model, Term, Details).
method(classesof, _, [Term, Direct, Models0], Classes) :-
    models(Models0, Models),
    must_be(boolean, Direct),
    term_name(Term, Resource),
    findall(C, ( member(Model, Models),
                 oro_exists(Model, Resource),
                 (   Direct == true
                 ->  oro_direct_classes_of(Model, Resource, Cs)
                 ;   oro_classes_of(Model, Resource, Cs)
                 ),
                 member(C0, Cs),
                 kb_json_term(C0, C)
               ), Classes0),
    sort(Classes0, Classes).
method(exist, _, [Stmts, Models0], Bool) :-
    models(Models0, Models),
    statements(Stmts),
    bool(exist(Models, Stmts), Bool).
method(find, _, [A, B, C, D], Result) :-
    (   patterns_first(A, B)
    ->  (   D == null
        ->  Models0 = C
        ;   C == null
        ->  Models0 = D
        ;   kb_error("find(patterns, vars, models) takes no constraints", [])
        ),
        Constraints = null
    ;   Constraints = C,
        Models0 = D
    ),
    models(Models0, Models),
    find(A, B, Constraints, Models, Result).
method(revise, _, [Stmts, Policy], Reply) :-
    (   is_dict(Policy)
    ->  true
    ;   kb_error("revise() expects a policy object, not ~q", [Policy])
    ),
    (   get_dict(method, Policy, How)
    ->  true
    ;   kb_error("the revision policy has no method", [])
    ),
    policy_value(Policy, models, null, Models0),
    policy_value(Policy, lifespan, 0, Lifespan),
    revise(How, Stmts, Models0, Lifespan, Reply).
method(add, _, [Stmts, Models, Lifespan], Reply) :-
    revise("add", Stmts, Models, Lifespan, Reply).
method(update, _, [Stmts, Models, Lifespan], Reply) :-
    revise("update", Stmts, Models, Lifespan, Reply).
method(retract, _, [Stmts, Models], Reply) :-
    revise("retract", Stmts, Models, 0, Reply).
method(remove, _, [Stmts, Models], Reply) :-
    revise("retract", Stmts, Models, 0, Reply).
method(safe_add, _, [Stmts, Models, Lifespan], Reply) :-
    revise("safe_add", Stmts, Models, Lifespan, Reply).
method(subscribe, Context, Values, Id) :-
    subscribe(Context, Values, Id).
method(sparql, _, [Query, Model0], JSON) :-
    must_be(text, Query),
    models(Model0, Models),
    (   Models = [Model]
    ->  true
    ;   kb_error("sparql() runs on one model, not ~q", [Model0])
    ),
    oro_sparql_json(Model, Query, Text),
    atom_json_dict(Text, JSON, [value_string_as(string)]).
method(load, _, [File, Models0], void) :-
    must_be(text, File),
    models(Models0, Models),
    atom_string(Path, File),
    forall(member(Model, Models), load(Model, Path)).
method(save, _, [Dir, Base, Models0], void) :-
    must_be(text, Dir),
    must_be(text, Base),
    models(Models0, Models),
    forall(member(Model, Models),
           ( format(atom(File), "~w/~w-~w.rdf", [Dir, Base, Model]),
             oro_save(Model, File)
           )).
method(clear, _, [], void) :-
    clear.
method(reset, _, [], void) :-
    clear.
method(check_consistency, _, [Models0], Bool) :-
    models(Models0, Models),
    bool(forall(member(M, Models), oro_consistent(M)), Bool).
method(explain, _, [Stmts, Models0], Maps) :-
    statements(Stmts),
    models(Models0, [Model|_]),
    oro_statements(Stmts, Triples, _),
    (   ground(Triples)
    ->  true
    ;   kb_error("explain() takes statements, not patterns", [])
    ),
    oro_explain_values(Model, Triples, Values),
    oro_encode_value(list(Values), Text),
    atom_json_dict(Text, Maps, [value_string_as(string)]).
method(similarities, _, [A, B, Models0], Pairs) :-
    models(Models0, [Model|_]),
    term_name(A, RA),
    term_name(B, RB),
    oro_similarities(Model, RA, RB, Similar),
    findall([P, V], ( member(similar(P0, V0), Similar),
                      kb_json_term(P0, P),
                      kb_json_term(V0, V)
                    ), Pairs).
method(differences, _, [A, B, Models0], Groups) :-
    models(Models0, [Model|_]),
    term_name(A, RA),
    term_name(B, RB),
    oro_differences(Model, RA, RB, Groups0),
    maplist(maplist(triple_json), Groups0, Groups).
method(discriminate, _, [Terms, Models0], _{total:Total, best:Best}) :-
    models(Models0, [Model|_]),
    must_be(list(text), Terms),
    maplist(term_name, Terms, Resources),
    oro_discriminate(Model, Resources, Total0, Best0),
    maplist(kb_json_term, Total0, Total),
    maplist(kb_json_term, Best0, Best).

param_text(Name=Default, Text) :-
    !,
    with_output_to(string(D), json_write_dict(current_output, Default)),
    format(string(Text), "~w=~w", [Name, D]).
param_text(Name, Name).

%   kb_version(-Version): the version of oro, from its pack.pl.

kb_version(Version) :-
    (   absolute_file_name(oro_home('pack.pl'), Pack,
                           [access(read), file_errors(fail)]),
        catch(setup_call_cleanup(open(Pack, read, In),
                                 pack_version(In, Version0),
                                 close(In)),
              _, fail)
    ->  Version = Version0
    ;   Version = unknown
    ).

pack_version(In, Version) :-
    read_term(In, Term, []),
    (   Term == end_of_file
    ->  fail
    ;   Term = version(Version)
    ->  true
    ;   pack_version(In, Version)
    ).

bool(Goal, Bool) :-
    (   call(Goal)
    ->  Bool = true
    ;   Bool = false
    ).

triple_json(rdf(S0, P0, O0), Text) :-
    maplist(oro_term_light_text, [S0, P0, O0], Parts),
    atomic_list_concat(Parts, ' ', Atom),
    atom_string(Atom, Text).

		 /*******************************
		 *            MODELS            *
		 *******************************/

%   models(+Spec, -Models): the resolved models a `models` parameter
%   names (see the module doc).

models(Spec, Models) :-
    (   ( Spec == null ; Spec == [] ; Spec == "" )
    ->  Models = [myself]
    ;   string(Spec)
    ->  models([Spec], Models)
    ;   is_list(Spec)
    ->  must_be(list(text), Spec),
        (   memberchk("all", Spec)
        ->  findall(M, oro_model(M), Models0)
        ;   maplist(model, Spec, Models0)
        ),
        sort(Models0, Models)
    ;   kb_error("models must be a list of model names, not ~q", [Spec])
    ).

model(Name, Model) :-
    atom_string(Atom, Name),
    (   memberchk(Atom, ['', default, myself])
    ->  Model = myself
    ;   catch(oro_resolve_model(Atom, Model), error(existence_error(_, _), _),
              fail)
    ->  true
    ;   oro_create_model(Atom),
        Model = Atom
    ).

		 /*******************************
		 *            CHANGES           *
		 *******************************/

statements(Stmts) :-
    (   is_list(Stmts),
        Stmts \== [],
        forall(member(S, Stmts), string(S))
    ->  true
    ;   kb_error("a non-empty list of statements is expected, not ~q",
                 [Stmts])
    ).

policy_value(Policy, Key, Default, Value) :-
    (   get_dict(Key, Policy, Value0)
    ->  Value = Value0
    ;   Value = Default
    ).

%   revise(+How, +Stmts, +Models, +Lifespan, -Reply): the revision
%   policies.  `add` adds (as minimalkb and ORO; knowledge_core
%   updates), `safe_add` adds what keeps each model consistent and
%   answers whether all was kept, `update` replaces the values of
%   functional properties, and so do `safe_update` and `revision`, as
%   in knowledge_core; `retract` removes statements and patterns.  The
%   whole batch is parsed before anything changes.

revise(How0, Stmts, Models0, Lifespan, Reply) :-
    must_be(text, How0),
    string_lower(How0, How),
    statements(Stmts),
    models(Models0, Models),
    (   memberchk(How, ["add", "safe_add", "update", "safe_update",
                        "revision"])
    ->  profile(Lifespan, Profile),
        oro_statements(Stmts, Triples, _),
        (   ground(Triples)
        ->  true
        ;   kb_error("statements to ~w cannot hold variables: ~q",
                     [How, Stmts])
        )
    ;   How == "retract"
    ->  Profile = longterm,
        oro_statements(Stmts, _, _)
    ;   kb_error("unknown revision method '~w'", [How0])
    ),
    revise_models(How, Models, Stmts, Profile, Reply).

revise_models("safe_add", Models, Stmts, Profile, Accepted) :-
    !,
    foldl(safe_add(Stmts, Profile), Models, true, Accepted).
revise_models(How, Models, Stmts, Profile, void) :-
    forall(member(Model, Models),
           revise_model(How, Model, Stmts, Profile)).

safe_add(Stmts, Profile, Model, Accepted0, Accepted) :-
    oro_safe_add(Model, Stmts, Profile, Accepted1),
    (   Accepted1 == true
    ->  Accepted = Accepted0
    ;   Accepted = false
    ).

revise_model("add", Model, Stmts, Profile) :-
    oro_add(Model, Stmts, Profile).
revise_model("update", Model, Stmts, Profile) :-
    oro_update(Model, Stmts, Profile).
revise_model("safe_update", Model, Stmts, Profile) :-
    oro_update(Model, Stmts, Profile).
revise_model("revision", Model, Stmts, Profile) :-
    oro_update(Model, Stmts, Profile).
revise_model("retract", Model, Stmts, _) :-
    oro_remove(Model, Stmts).

profile(Lifespan, Profile) :-
    (   number(Lifespan),
        Lifespan >= 0
    ->  (   Lifespan =:= 0
        ->  Profile = longterm
        ;   Profile = lifespan(Lifespan)
        )
    ;   Lifespan == null
    ->  Profile = longterm
    ;   kb_error("lifespan must be a number of seconds >= 0, not ~q",
                 [Lifespan])
    ).

clear :-
    kb_events_reset,
    oro_reset.

load(Model, Path) :-
    (   exists_file(Path)
    ->  true
    ;   existence_error(file, Path)
    ),
    file_name_extension(_, Ext0, Path),
    downcase_atom(Ext0, Ext),
    (   memberchk(Ext-Format, [owl-xml, rdf-xml, xml-xml, ttl-turtle,
                              n3-turtle, nt-ntriples])
    ->  true
    ;   kb_error("cannot tell the format of ~w (.owl, .rdf, .ttl, .nt)",
                 [Path])
    ),
    oro_scratch_load(Path, Format, Triples),
    oro_add(Model, Triples).

%   oro_scratch_load(+Path, +Format, -Triples): the triples of a file,
%   read into a graph of their own and dropped.

oro_scratch_load(Path, Format, Triples) :-
    gensym(kb_load_, Name),
    oro_shared_graph(scratch(Name), Graph),
    oro_scratch_graph(Graph),
    setup_call_cleanup(
        rdf_load(Path, [graph(Graph), format(Format), silent(true)]),
        findall(rdf(S, P, O), rdf(S, P, O, Graph), Triples),
        rdf_unload_graph(Graph)).

		 /*******************************
		 *           QUESTIONS          *
		 *******************************/

term_name(Term, Resource) :-
    (   string(Term)
    ->  oro_name_iri(Term, Resource)
    ;   kb_error("a name is expected, not ~q", [Term])
    ).

about(Model, R, R, P, O) :-
    oro_holds(Model, R, P, O).
about(Model, R, S, R, O) :-
    oro_holds(Model, S, R, O).
about(Model, R, S, P, R) :-
    oro_holds(Model, S, P, R).

%   lookup(+Model, +Text, -Pair): [Name, Kind] of what Text names by
%   label or local name (oro_lookup/3), else of the literal Text if the
%   model holds it (`literal`), else of the resource Text names
%   (`rdfs:label`), `undecided` if it has no kind.

lookup(Model, Text, [Name, Kind]) :-
    oro_lookup(Model, Text, Matches),
    (   Matches \== []
    ->  member(R-Kind0, Matches),
        kb_json_term(R, Name),
        atom_string(Kind0, Kind)
    ;   format(string(Pattern), "?s ?p ~w", [Text]),
        catch(oro_statements([Pattern], [rdf(_, _, O)], _), _, fail),
        O = literal(_)
    ->  oro_check(Model, [Pattern]),
        Name = Text,
        Kind = "literal"
    ;   catch(oro_name_iri(Text, R), _, fail),
        oro_exists(Model, R)
    ->  kb_json_term(R, Name),
        (   oro_resource_kind(Model, R, _)
        ->  oro_resource_kind(Model, R, Kind0),
            atom_string(Kind0, Kind)
        ;   Kind = "undecided"
        )
    ).

labels(Models, Resource, Labels) :-
    rdf_equal(rdfs:label, Label),
    findall(Key-Text,
            ( member(Model, Models),
              oro_holds(Model, Resource, Label, Literal),
              Literal = literal(L),
              label_key(L, Key, Text)
            ),
            Pairs0),
    sort(1, @>=, Pairs0, Pairs1),
    (   memberchk(default-_, Pairs1)
    ->  Pairs = Pairs1
    ;   memberchk(en-English, Pairs1)
    ->  Pairs = [default-English|Pairs1]
    ;   kb_json_term(Resource, Name),
        Pairs = [default-Name|Pairs1]
    ),
    dict_pairs(Labels, _, Pairs).

label_key(lang(Lang, Text0), Key, Text) :-
    !,
    downcase_atom(Lang, Key),
    atom_string(Text0, Text).
label_key(type(_, Text0), default, Text) :-
    !,
    atom_string(Text0, Text).
label_key(Text0, default, Text) :-
    atom_string(Text0, Text).

details(Model, Term, Details) :-
    term_name(Term, Resource),
    oro_resource_details(Model, Resource, "en", D),
    labels([Model], Resource, Labels),
    maplist(kb_json_term, D.same_as, SameAs),
    maplist(attribute_json, D.attributes, Attributes),
    atom_string(D.type, Type),
    Details = _{id:Term, name:D.name, label:Labels, type:Type,
                sameAs:SameAs, attributes:Attributes}.

attribute_json(attribute(Name, Id, Values0),
               _{name:Name, id:Id, values:Values}) :-
    maplist(value_json, Values0, Values).

value_json(value(Label, Term), _{id:Id, label:Label}) :-
    kb_json_term(Term, Id).

%   exist(+Models, +Stmts): the statements hold in every model; with
%   variables, the patterns (sharing them) have a solution in each.

exist(Models, Stmts) :-
    oro_statements(Stmts, Triples, _),
    forall(member(Model, Models),
           (   ground(Triples)
           ->  oro_check(Model, Stmts)
           ;   kb_rows([Model], Stmts, [], _, [_|_])
           )).

%   find(+A, +B, +Constraints, +Models, -Result): minimalkb's
%   find(vars, patterns, constraints, models) or knowledge_core's
%   find(patterns, vars, models), told apart by their first argument
%   (variables have no space; patterns have).  knowledge_core's form
%   answers rows (dicts) whatever the number of variables, and the
%   patterns themselves when they hold no variable (`[]` if they are
%   not true); minimalkb's form answers the values of a single
%   variable, or rows for several.

find(A, B, Constraints, Models, Result) :-
    (   patterns_first(A, B)
    ->  Patterns = A,
        vars_param(B, Vars),
        Constraints = null,
        statements(Patterns),
        (   oro_statements(Patterns, Triples, _),
            ground(Triples)
        ->  (   exist(Models, Patterns)
            ->  Result = Patterns
            ;   Result = []
            )
        ;   rows(Models, Patterns, Vars, Result)
        )
    ;   vars_param(A, Vars),
        Patterns = B,
        statements(Patterns),
        constraints(Constraints, Filters),
        (   Filters \== []
        ->  filtered(Models, Vars, Patterns, Filters, Result)
        ;   Vars = [Var]
        ->  kb_rows(Models, Patterns, [Var], _, Rows),
            findall(V, member([V], Rows), Result)
        ;   rows(Models, Patterns, Vars, Result)
        )
    ).

patterns_first(A, _) :-
    is_list(A),
    A = [First|_],
    string(First),
    sub_string(First, _, _, _, " "),
    !.

vars_param(Vars, List) :-
    (   ( Vars == null ; Vars == "" ; Vars == [""] )
    ->  List = []
    ;   string(Vars)
    ->  List = [Vars]
    ;   is_list(Vars),
        forall(member(V, Vars), string(V))
    ->  List = Vars
    ;   kb_error("variables must be a list of names, not ~q", [Vars])
    ).

constraints(C, Filters) :-
    (   ( C == null ; C == [] )
    ->  Filters = []
    ;   is_list(C),
        forall(member(F, C), string(F))
    ->  Filters = C
    ;   kb_error("constraints must be a list of SPARQL filters, not ~q", [C])
    ).

rows(Models, Patterns, Vars, Dicts) :-
    kb_rows(Models, Patterns, Vars, Keys, Rows),
    findall(Dict,
            ( member(Row, Rows),
              pairs_keys_values(Pairs, Keys, Row),
              dict_pairs(Dict, _, Pairs)
            ),
            Dicts).

%   filtered(+Models, +Vars, +Patterns, +Filters, -Result): minimalkb's
%   constraints, as SPARQL filters (oro_find/5), for one variable.

filtered(Models, Vars, Patterns, Filters, Result) :-
    (   Vars = [Var]
    ->  true
    ;   kb_error("find() with constraints takes one variable", [])
    ),
    findall(V, ( member(Model, Models),
                 oro_find(Model, Var, Patterns, Filters, Values),
                 member(V0, Values),
                 kb_json_term(V0, V)
               ), Result0),
    sort(Result0, Result).

		 /*******************************
		 *            EVENTS            *
		 *******************************/

%   subscribe(+Context, +Values, -Id): knowledge_core's
%   subscribe(patterns, one_shot, models), or minimalkb's
%   subscribe(type, trigger, var, patterns[, models]) with type
%   NEW_INSTANCE or NEW_CLASS_INSTANCE (patterns: one class), `_ONE_SHOT`
%   in the type or the trigger for one firing.

subscribe(Context, [Patterns, OneShot, Models0], Id) :-
    is_list(Patterns),
    !,
    statements(Patterns),
    (   OneShot == null
    ->  Bool = false
    ;   must_be(boolean, OneShot),
        Bool = OneShot
    ),
    models(Models0, Models),
    client_queue(Context, Queue),
    kb_subscribe(Queue, Models, Patterns, rows(Bool), Id).
subscribe(Context, [Type0, Trigger0, Var0, Patterns0|Rest], Id) :-
    !,
    must_be(text, Type0),
    must_be(text, Trigger0),
    string_upper(Type0, Type),
    string_upper(Trigger0, Trigger),
    (   ( sub_string(Type, _, _, _, "ONE_SHOT")
        ; sub_string(Trigger, _, _, _, "ONE_SHOT")
        )
    ->  OneShot = true
    ;   OneShot = false
    ),
    (   sub_string(Type, 0, _, _, "NEW_CLASS_INSTANCE")
    ->  (   Patterns0 = [Class],
            string(Class)
        ->  format(string(P), "?instance rdf:type ~w", [Class]),
            Patterns = [P],
            Var = "instance"
        ;   kb_error("NEW_CLASS_INSTANCE takes one class", [])
        )
    ;   sub_string(Type, 0, _, _, "NEW_INSTANCE")
    ->  Patterns = Patterns0,
        statements(Patterns),
        (   string(Var0)
        ->  Var = Var0
        ;   kb_error("NEW_INSTANCE needs a variable", [])
        )
    ;   kb_error("unknown event type '~w' (NEW_INSTANCE, \c
                  NEW_CLASS_INSTANCE)", [Type0])
    ),
    (   Rest = [Models0]
    ->  true
    ;   Models0 = null
    ),
    models(Models0, Models),
    client_queue(Context, Queue),
    kb_subscribe(Queue, Models, Patterns, values(Var, OneShot), Id).
subscribe(_, Values, _) :-
    kb_error("subscribe(patterns, one_shot, models) or subscribe(type, \c
              trigger, var, patterns, models) expected, not ~q", [Values]).
